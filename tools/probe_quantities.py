"""What each column of probes.csv measures: its physical quantity, SI unit and a readable label.

A probe writes the columns NAME.COMPONENT of its kind (docs/scene-format.md, "probes"); the kind
is recognised from the set of components. `probe_panels` groups a probe's columns into one panel
per physical quantity, so that a contact count, forces, moments and a penetration never share
an axis.
"""

from dataclasses import dataclass, field

import numpy as np

ENERGY_TERMS = ("kinetic", "strain", "gravity", "work", "dissipated")
XYZ = ("x", "y", "z")
DIMENSIONLESS = "–"
# Quantities that take whole values only (their axes get integer ticks).
COUNTS = ("number of contacts", "thread index", "contact mode", "in contact (0/1)",
          "escaped (0/1)")


def _vector(prefix, quantity, unit, legend, axes=XYZ):
    """{prefix+axis: (quantity, unit, legend with {axis})} for the three axes."""
    return {prefix + a: (quantity, unit, legend.replace("{axis}", a)) for a in axes}


# (quantity, unit, legend) of each component, by probe kind; "{name}" is the probe's name.
KINDS = {
    "contact": {
        "active": ("number of contacts", DIMENSIONLESS, "active contacts on {name}"),
        "normal_force": ("force", "N", "normal force on {name} (Σ F_n)"),
        "friction_force": ("force", "N", "friction force on {name} (Σ |f_t|)"),
        **_vector("f", "force", "N", "force on {name}, {axis} (world)"),
        **_vector("m", "moment", "N m", "moment on {name} about its centre, {axis}"),
        "max_penetration": ("penetration", "m", "deepest penetration into {name}"),
    },
    "body_pose": {
        **_vector("", "position", "m", "position, {axis} ({name})"),
        **{f"q{a}": ("orientation (unit quaternion)", DIMENSIONLESS, f"q_{a} ({{name}})")
           for a in "wxyz"},
    },
    "body_velocity": {
        **_vector("v", "velocity", "m/s", "velocity, world {axis} ({name})"),
        **_vector("w", "angular velocity", "rad/s", "angular velocity about body {axis} ({name})"),
    },
    "energy": {
        "kinetic": ("energy", "J", "kinetic energy"),
        "strain": ("energy", "J", "strain energy"),
        "gravity": ("energy", "J", "potential of gravity"),
        "work": ("energy", "J", "work of the applied loads"),
        "dissipated": ("energy", "J", "dissipated energy"),
    },
    "max_tension": {
        "tension": ("tension", "N", "largest thread tension ({name})"),
        "thread": ("thread index", DIMENSIONLESS, "index j of the thread t<j> carrying it ({name})"),
    },
    "link_force": {
        "tension": ("tension", "N", "tension of {name}"),
        **_vector("f", "force", "N", "force of {name} on its second point, {axis}"),
    },
    "joint_reaction": {
        **_vector("f", "force", "N", "reaction force of {name}, {axis}"),
        **_vector("m", "moment", "N m", "reaction moment of {name}, {axis}"),
    },
    "clearance_joint": {
        **_vector("e", "eccentricity", "m", "eccentricity of {name}, {axis}"),
        "penetration": ("penetration", "m", "penetration in {name}"),
        "normal_force": ("force", "N", "normal force in {name}"),
        "friction_force": ("force", "N", "friction force in {name}"),
        "friction_moment": ("moment", "N m", "friction moment in {name}"),
        "mode": ("contact mode", DIMENSIONLESS, "mode of {name} (0 free, 1 contact, 2 impact)"),
    },
    "position": _vector("", "position", "m", "position of {name}, {axis}"),
    "velocity": _vector("v", "velocity", "m/s", "velocity of {name}, {axis}"),
    "mouth_area": {"area": ("area", "m²", "mouth area of {name}")},
    "distance": {"distance": ("distance", "m", "distance travelled by {name}")},
    # docs/theory.md, "Capture metrics"
    "capture": {
        "contact": ("in contact (0/1)", DIMENSIONLESS, "net touches the target ({name})"),
        "enclosed": ("fraction", DIMENSIONLESS, "capture quality: target ball enclosed ({name})"),
        "mouth_ratio": ("fraction", DIMENSIONLESS, "mouth area / initial ({name})"),
        "knot_coverage": ("fraction", DIMENSIONLESS, "knots touching the target ({name})"),
        "thread_coverage": ("fraction", DIMENSIONLESS, "threads touching the target ({name})"),
        "thread_tension": ("tension", "N", "largest thread tension ({name})"),
        "thread_load": ("tension / breaking force", DIMENSIONLESS, "threads ({name})"),
        "tether_tension": ("tension", "N", "largest tether tension ({name})"),
        "tether_load": ("tension / breaking force", DIMENSIONLESS, "tether ({name})"),
        "escaped": ("escaped (0/1)", DIMENSIONLESS, "target escaped ({name})"),
    },
}


def probe_kind(components):
    """The kind of probe whose columns are `components` (names), or None when unknown."""
    names = set(components)
    for kind, table in KINDS.items():
        if names == set(table):
            return kind
    return None


@dataclass
class Curve:
    label: str
    values: np.ndarray


@dataclass
class Panel:
    """One physical quantity: every curve on it has the unit `unit`."""
    quantity: str
    unit: str
    curves: list = field(default_factory=list)

    @property
    def ylabel(self):
        return f"{self.quantity} [{self.unit}]"


def describe(name, component, kind):
    """(quantity, unit, legend) of the column NAME.COMPONENT of a probe of `kind`."""
    quantity, unit, legend = KINDS.get(kind, {}).get(
        component, (f"{component} (not an ancfnet column)", "unknown unit", f"{name}.{component}"))
    return quantity, unit, legend.replace("{name}", name)


def energy_balance(components):
    """kinetic + strain + gravity + dissipated − work: constant in a consistent run (J)."""
    c = components
    return c["kinetic"] + c["strain"] + c["gravity"] + c["dissipated"] - c["work"]


def probe_panels(name, components):
    """The probe's columns as a list of Panels, one per (quantity, unit), in column order.

    An energy probe's panel also gets the balance (energy_balance)."""
    kind = probe_kind(components)
    panels = {}
    for component, values in components.items():
        quantity, unit, legend = describe(name, component, kind)
        panel = panels.setdefault((quantity, unit), Panel(quantity, unit))
        panel.curves.append(Curve(legend, values))
    if kind == "energy":
        balance = Curve("balance: kinetic + strain + gravity + dissipated − work",
                        energy_balance(components))
        panels[("energy", "J")].curves.append(balance)
    return list(panels.values())

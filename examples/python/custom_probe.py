"""A probe written in Python: the swing angle of the flexible pendulum of examples/pendulum.yaml
(the chord from the pin to the tip, below the horizontal) and the tip's speed, computed from the
state at each output step while the run writes its own outputs.

Usage: /usr/bin/python3 examples/python/custom_probe.py [END_TIME]  (s, default 1.0)"""
import math
import pathlib
import sys
import tempfile

import numpy as np

import ancfnet

# Each node of a cable holds its position r and slope r' (6 coordinates); the tip is the last.
TIP_POSITION = slice(-6, -3)


def swing_angle(q):
    """Angle (degrees) of the chord from the pin at the origin to the tip below the horizontal."""
    x, _, z = q[TIP_POSITION]
    return math.degrees(math.atan2(-z, x))


def main():
    end_time = sys.argv[1] if len(sys.argv) > 1 else "1.0"
    text = (pathlib.Path(__file__).parents[1] / "pendulum.yaml").read_text()
    scene = ancfnet.parse_scene(text.replace("end_time: 1.0", f"end_time: {end_time}"))
    with tempfile.TemporaryDirectory() as out:
        simulation = ancfnet.Simulation(scene, out)
        print("   t (s)   angle (deg)   tip speed (m/s)")
        while simulation.advance():
            speed = np.linalg.norm(simulation.v[TIP_POSITION])
            print(f"{simulation.t:8.3f} {swing_angle(simulation.q):13.2f} {speed:17.3f}")
        print(f"status: {simulation.summary['status']}, {simulation.summary['steps']} steps")


main()

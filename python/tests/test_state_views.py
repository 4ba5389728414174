"""Simulation.q and .v are read-only numpy views of the run's state, not copies."""

import numpy as np
import pytest

import ancfnet


@pytest.fixture
def simulation(tmp_path, pendulum_text):
    return ancfnet.Simulation(ancfnet.parse_scene(pendulum_text), tmp_path)


def test_views_follow_the_state_without_copies(simulation):
    assert simulation.advance()
    q, v = simulation.q, simulation.v
    q_start = q.copy()
    assert np.all(v == 0.0)  # released from rest

    assert simulation.advance()
    assert simulation.t == pytest.approx(0.01)
    assert not np.array_equal(q, q_start)  # the same view now shows the new state
    assert np.any(v != 0.0)
    assert np.array_equal(q, simulation.q)
    assert np.shares_memory(q, simulation.q)


def test_views_are_read_only_and_keep_the_simulation_alive(simulation):
    simulation.advance()
    q = simulation.q
    assert q.base is simulation
    assert q.dtype == np.float64 and q.shape == simulation.v.shape
    with pytest.raises(ValueError):
        q[0] = 1.0


def test_the_initial_state_before_the_first_step(simulation):
    assert simulation.t == 0.0
    assert not simulation.finished and simulation.summary is None
    assert simulation.q[-6:-3].tolist() == [1.2, 0.0, 0.0]  # the tip (examples/pendulum.yaml)

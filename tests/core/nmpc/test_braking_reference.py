"""The braking backup's reference: decelerate along the current heading, then hold."""

from __future__ import annotations

import numpy as np
import pytest

from core.nmpc.reference import BrakingReference


def _reference(velocity: tuple[float, float] = (0.3, 0.4)) -> BrakingReference:
    return BrakingReference(start_time_s=2.0, position_m=np.array([1.0, -1.0]),
                            velocity_m_s=np.array(velocity), height_m=0.45, yaw_rad=0.3,
                            deceleration_m_s2=0.5)


def test_decelerates_along_the_heading_then_holds_where_it_stops() -> None:
    reference = _reference()
    speed, heading = 0.5, np.array([0.6, 0.8])
    stop_s = speed / 0.5
    start = reference.payload_state(2.0)
    np.testing.assert_allclose(start[0:2], [1.0, -1.0])
    np.testing.assert_allclose(start[3:5], [0.3, 0.4])
    halfway = reference.payload_state(2.0 + stop_s / 2)
    np.testing.assert_allclose(halfway[3:5], heading * speed / 2, atol=1e-12)
    rest = np.array([1.0, -1.0]) + heading * speed ** 2 / (2 * 0.5)
    for t in (2.0 + stop_s, 10.0, np.inf):
        state = reference.payload_state(t)
        np.testing.assert_allclose(state[0:2], rest, atol=1e-12)
        assert not state[3:6].any()
    np.testing.assert_allclose(reference.goal_m(), rest)
    # height and yaw held; no turning, no vertical motion
    states = np.array([reference.payload_state(t) for t in np.linspace(0, 5, 51)])
    assert np.all(states[:, 2] == 0.45) and np.all(states[:, 8] == 0.3)
    assert not states[:, 9:12].any()
    # speed never increases, and the path never turns back
    speeds = np.linalg.norm(states[:, 3:5], axis=1)
    assert np.all(np.diff(speeds) <= 1e-12)
    assert np.all(np.diff(states[:, 0:2] @ heading) >= -1e-12)


def test_before_its_start_it_holds_the_start_and_at_rest_it_stays() -> None:
    np.testing.assert_allclose(_reference().payload_state(0.0)[0:2], [1.0, -1.0])
    still = _reference(velocity=(0.0, 0.0))
    for t in (0.0, 2.0, 5.0):
        state = still.payload_state(t)
        np.testing.assert_allclose(state[0:2], [1.0, -1.0])
        assert not state[3:6].any()


@pytest.mark.parametrize("deceleration", [0.2, 1.0, 3.0])
def test_stopping_distance_is_v_squared_over_two_a(deceleration: float) -> None:
    reference = BrakingReference(0.0, np.zeros(2), np.array([0.3, 0.0]), 0.45, 0.0, deceleration)
    assert reference.goal_m()[0] == pytest.approx(0.09 / (2 * deceleration))

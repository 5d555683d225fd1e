"""The run sequence's transition table (``deploy.safety.run_sequence``), row by row, on a real
supervisor over a Go2 and an A1."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import pytest

from deploy.config.deploy_config import PostureConfig
from deploy.safety.posture import sitting_posture, standing_posture
from deploy.safety.preflight import PreflightCheck, PreflightReport
from deploy.safety.run_sequence import (
    SOURCES,
    Braking,
    RunEvents,
    RunSequence,
    SequenceSettings,
)
from deploy.safety.settings import SupervisorSettings
from deploy.safety.supervisor import SafetyState, SafetySupervisor
from drivers.interfaces import MocapFrame

S = SafetyState
POSTURE = PostureConfig(stand_up_s=1.0, sit_down_s=0.5, settle_s=0.2, final_damping_s=0.3)


@dataclass
class Operator:
    """The stop request, the operator's answer and the pre-flight verdict, as a test sets them."""

    stop: bool = False
    answer: bool | None = True
    preflight_ok: bool = True
    asked: list[str] = field(default_factory=list)

    def stop_requested(self) -> bool:
        return self.stop

    def confirm(self) -> bool | None:
        self.asked.append("confirm")
        return self.answer

    def preflight(self, measurements, link_errors) -> PreflightReport:
        self.asked.append("preflight")
        return PreflightReport([PreflightCheck("links", self.preflight_ok, "test")])


@pytest.fixture
def operator() -> Operator:
    return Operator()


def _sequence(limits, operator: Operator, kind: str = "deploy", said: list | None = None,
              recorder_failure_stops: bool = True) -> RunSequence:
    supervisor = SafetySupervisor(SupervisorSettings(), limits)
    names = [robot.name for robot in limits]
    sequence = RunSequence(
        supervisor, SequenceSettings(kind, 3.0, POSTURE, preflight_timeout_s=1.0,  # type: ignore[arg-type]
                                     max_armed_s=0.5, max_plan_age_s=0.25,
                                     controlled_stop_s=1.0,
                                     recorder_failure_stops=recorder_failure_stops),
        {n: standing_posture(n.split("_")[0]) for n in names},
        {n: sitting_posture(n.split("_")[0], POSTURE.sit_lowering_m) for n in names},
        operator.stop_requested, operator.confirm, operator.preflight,
        (said if said is not None else []).append)
    supervisor.on_transition = lambda tr: sequence.entered(tr.target, tr.time_s)
    return sequence


def _events(t: float, standing, **fields) -> RunEvents:
    return RunEvents(t, dict(standing), **fields)


def _to(sequence: RunSequence, state: SafetyState, standing, t: float = 0.0) -> float:
    """Drive ``sequence`` (deploy kind) to ``state`` through the planned rows; the time."""
    route = [S.PREFLIGHT, S.STANDING_UP, S.ARMED, S.RUNNING, S.SITTING_DOWN]
    for target in route[route.index(sequence.state) + 1:route.index(state) + 1]:
        while sequence.state != target:
            t += 0.01
            sequence.at_tick_start(_events(t, standing))
            sequence.before_commands(_events(t, standing, plan_start_s=t))
            ready = target == S.RUNNING
            sequence.at_tick_end(_events(t, standing, plan_ready=ready, plan_start_s=t))
            if target == S.SITTING_DOWN and sequence.state == S.RUNNING:
                t += 3.0
            assert t < 20.0, sequence.state
    return t


def test_every_state_has_a_command_source() -> None:
    assert set(SOURCES) == set(SafetyState)
    assert SOURCES[S.RUNNING] == "plan" and SOURCES[S.SAFE_STOP] == "damping"


# --- rows 1-3: tick start ------------------------------------------------------------------
@pytest.mark.parametrize("state", [S.STANDING_UP, S.ARMED, S.RUNNING])
def test_row_1_the_watchdog_trips_an_active_state(limits, standing, operator, state) -> None:
    sequence = _sequence(limits, operator)
    t = _to(sequence, state, standing)
    sequence.at_tick_start(_events(t, standing, watchdog_tripped=True))
    assert sequence.state == S.SAFE_STOP and "watchdog" in sequence.supervisor.fault
    assert sequence.source == "damping"


def test_row_2_a_standing_run_starts_running_at_once(limits, standing, operator) -> None:
    sequence = _sequence(limits, operator, kind="standing")
    assert sequence.at_tick_start(_events(0.0, standing)) == (True, False)
    assert sequence.state == S.RUNNING and sequence.source == "plan"


@pytest.mark.parametrize("stop", [False, True])
def test_row_3_a_standing_run_ends_standing(limits, standing, operator, stop) -> None:
    sequence = _sequence(limits, operator, kind="standing")
    sequence.at_tick_start(_events(0.0, standing))
    assert sequence.at_tick_start(_events(1.0, standing)) == (False, False)
    operator.stop = stop
    t = 1.5 if stop else 3.0
    assert sequence.at_tick_start(_events(t, standing)) == (False, True)
    assert sequence.state == S.DONE and sequence.stopped_early is stop
    assert sequence.ended_by == ("stop requested" if stop else "ran 3 s")


# --- rows 4-5: before the commands ---------------------------------------------------------
def test_row_4_a_lost_nmpc_trips_before_the_commands(limits, standing, operator) -> None:
    sequence = _sequence(limits, operator)
    t = _to(sequence, S.ARMED, standing)
    sequence.before_commands(_events(t, standing, nmpc_lost="pipe closed", plan_start_s=t))
    assert sequence.state == S.SAFE_STOP
    assert sequence.supervisor.fault == "NMPC process lost: pipe closed"


def test_row_5_an_old_plan_trips_only_while_running(limits, standing, operator) -> None:
    sequence = _sequence(limits, operator)
    t = _to(sequence, S.ARMED, standing)
    sequence.before_commands(_events(t + 0.4, standing, plan_start_s=t))  # ARMED: no plan yet
    assert sequence.state == S.ARMED
    t = _to(sequence, S.RUNNING, standing, t)
    sequence.before_commands(_events(t + 0.25, standing, plan_start_s=t))  # at the limit
    assert sequence.state == S.RUNNING
    sequence.before_commands(_events(t + 0.26, standing, plan_start_s=t))
    assert sequence.state == S.SAFE_STOP and "NMPC stalled" in sequence.supervisor.fault


# --- rows 6-8: tick end, faults ------------------------------------------------------------
@pytest.mark.parametrize(("fields", "cause"), [
    ({"send_failed": "socket closed"}, "send failed: socket closed"),
    ({"nmpc_lost": "pipe closed"}, "NMPC process lost: pipe closed"),
    ({"recorder_failed": "disk full"}, "flight recorder failed: disk full")])
def test_rows_6_to_8_faults_at_the_tick_end(limits, standing, operator, fields, cause) -> None:
    said: list[str] = []
    sequence = _sequence(limits, operator, said=said)
    t = _to(sequence, S.RUNNING, standing)
    sequence.at_tick_end(_events(t, standing, plan_ready=True, **fields))
    assert sequence.state == S.SAFE_STOP and sequence.supervisor.fault == cause
    assert ("ERROR: flight recorder failed" in " ".join(said)) == ("recorder_failed" in fields)


def test_row_8_a_failed_recorder_only_warns_when_so_configured(limits, standing, operator
                                                                ) -> None:
    said: list[str] = []
    sequence = _sequence(limits, operator, said=said, recorder_failure_stops=False)
    t = _to(sequence, S.RUNNING, standing)
    sequence.at_tick_end(_events(t, standing, plan_ready=True, recorder_failed="disk full"))
    assert sequence.state == S.RUNNING and "disk full" in said[-1]


# --- row 9: braking ------------------------------------------------------------------------
def test_row_9_braking_long_enough_is_a_controlled_stop(limits, standing, operator) -> None:
    said: list[str] = []
    sequence = _sequence(limits, operator, said=said)
    t = _to(sequence, S.RUNNING, standing)
    braking = Braking(t, "braking: test")
    sequence.at_tick_end(_events(t + 0.99, standing, plan_ready=True, braking=braking))
    assert sequence.state == S.RUNNING and said[-1].endswith("braking: test")
    sequence.at_tick_end(_events(t + 1.01, standing, plan_ready=True, braking=braking))
    assert sequence.state == S.SITTING_DOWN and sequence.controlled_stop
    assert sequence.source == "posture" and set(sequence.moves) == {r.name for r in limits}
    assert sequence.ended_by.startswith("controlled stop: braking since")
    assert sum("braking: test" in line for line in said) == 1  # said once


# --- rows 10-12: pre-flight ----------------------------------------------------------------
def test_row_10_a_stop_in_preflight_ends_the_run(limits, standing, operator) -> None:
    sequence = _sequence(limits, operator)
    operator.stop = True
    sequence.at_tick_end(_events(0.01, standing))
    assert sequence.state == S.DONE and sequence.ended_by == "stop requested during pre-flight"


def test_row_11_passing_checks_stand_the_team_up(limits, standing, operator) -> None:
    sequence = _sequence(limits, operator)
    assert sequence.source == "limp"
    sequence.at_tick_end(_events(0.01, standing))
    assert sequence.state == S.STANDING_UP and sequence.report is not None
    assert sequence.report.ok and sequence.source == "posture"
    goal = sequence.moves["go2_0"].command(0.01 + POSTURE.stand_up_s)
    np.testing.assert_allclose(goal.position_rad, sequence.standing["go2_0"])


def test_row_12_failing_checks_time_out(limits, standing, operator) -> None:
    sequence = _sequence(limits, operator)
    operator.preflight_ok = False
    sequence.at_tick_end(_events(0.5, standing))
    assert sequence.state == S.PREFLIGHT
    sequence.at_tick_end(_events(1.01, standing))
    assert sequence.state == S.DONE and sequence.ended_by == "pre-flight failed"


# --- rows 13-15: standing up ---------------------------------------------------------------
def test_row_13_a_stop_while_standing_up_sits_down(limits, standing, operator) -> None:
    sequence = _sequence(limits, operator)
    t = _to(sequence, S.STANDING_UP, standing)
    operator.stop = True
    sequence.at_tick_end(_events(t + 0.01, standing))
    assert sequence.state == S.SITTING_DOWN
    assert sequence.ended_by == "stop requested while standing up"


@pytest.mark.parametrize(("answer", "state"), [(True, S.ARMED), (False, S.SITTING_DOWN),
                                               (None, S.STANDING_UP)])
def test_rows_14_15_the_operator_is_asked_once_stood_and_settled(limits, standing, operator,
                                                                 answer, state) -> None:
    sequence = _sequence(limits, operator)
    t = _to(sequence, S.STANDING_UP, standing)
    operator.answer = answer
    assert sequence.at_tick_end(_events(t + 1.19, standing)) == (False, False)
    assert "confirm" not in operator.asked  # not yet stood and settled
    start_plans, _ = sequence.at_tick_end(_events(t + 1.2, standing))
    assert sequence.state == state and start_plans is (answer is True)
    assert operator.asked.count("confirm") == 1


# --- rows 16-18: armed ---------------------------------------------------------------------
def test_row_16_a_stop_while_armed_sits_down(limits, standing, operator) -> None:
    sequence = _sequence(limits, operator)
    t = _to(sequence, S.ARMED, standing)
    operator.stop = True
    sequence.at_tick_end(_events(t + 0.01, standing, plan_ready=True))
    assert sequence.state == S.SITTING_DOWN and sequence.ended_by == "stop requested while armed"


def test_row_17_the_first_plan_starts_the_run(limits, standing, operator) -> None:
    sequence = _sequence(limits, operator)
    t = _to(sequence, S.ARMED, standing)
    frame = MocapFrame(t, {})
    sequence.at_tick_end(_events(t + 0.01, standing, plan_ready=False))
    assert sequence.state == S.ARMED
    sequence.at_tick_end(_events(t + 0.02, standing, plan_ready=True, frame=frame))
    assert sequence.state == S.RUNNING and sequence.frames["start"] is frame


def test_row_18_no_plan_in_time_is_a_safe_stop(limits, standing, operator) -> None:
    sequence = _sequence(limits, operator)
    t = _to(sequence, S.ARMED, standing)
    sequence.at_tick_end(_events(t + 0.5, standing))
    assert sequence.state == S.ARMED
    sequence.at_tick_end(_events(t + 0.51, standing))
    assert sequence.state == S.SAFE_STOP and "no NMPC plan" in sequence.supervisor.fault


# --- rows 19-22: the end -------------------------------------------------------------------
@pytest.mark.parametrize("stop", [False, True])
def test_row_19_a_deploy_run_ends_sitting_down(limits, standing, operator, stop) -> None:
    sequence = _sequence(limits, operator)
    t = _to(sequence, S.RUNNING, standing)
    sequence.at_tick_end(_events(t + 2.99, standing, plan_ready=True))
    assert sequence.state == S.RUNNING
    operator.stop = stop
    end_s = t + (2.995 if stop else 3.01)
    sequence.at_tick_end(_events(end_s, standing, plan_ready=True, frame=MocapFrame(t, {})))
    assert sequence.state == S.SITTING_DOWN and "end" in sequence.frames
    assert sequence.ended_by == ("stop requested" if stop else "ran 3 s")


def test_rows_20_22_sitting_down_then_done_then_over(limits, standing, operator) -> None:
    sequence = _sequence(limits, operator)
    t = _to(sequence, S.SITTING_DOWN, standing)
    sequence.at_tick_end(_events(t + 0.49, standing))
    assert sequence.state == S.SITTING_DOWN
    sequence.at_tick_end(_events(t + 0.51, standing))
    assert sequence.state == S.DONE and sequence.source == "damping"
    assert sequence.at_tick_end(_events(t + 0.79, standing)) == (False, False)
    assert sequence.at_tick_end(_events(t + 0.81, standing)) == (False, True)


def test_row_21_a_safe_stop_damps_then_is_done(limits, standing, operator) -> None:
    sequence = _sequence(limits, operator)
    t = _to(sequence, S.RUNNING, standing)
    sequence.abort(t, "exception: test")
    assert sequence.state == S.SAFE_STOP
    sequence.at_tick_end(_events(t + 0.29, standing))
    assert sequence.state == S.SAFE_STOP and sequence.ended_by == "safe stop: exception: test"
    sequence.at_tick_end(_events(t + 0.3, standing))
    assert sequence.state == S.DONE

"""ADMM local solves on `porter agent` processes over Zenoh: the same plans as in this process,
messages that are not for the team dropped and counted, agents that are missing, hold another
problem or die reported, never hung on."""

from __future__ import annotations

import os
import signal
import threading
import time
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

from core.admm.admm_executor import LocalSolverSpec
from core.admm.admm_mpc import DistributedMpc
from core.admm.admm_peer_mpc import PeerDistributedMpc
from core.model.team import TeamModel
from deploy.agents import wire
from deploy.agents.zenoh_executor import ZenohExecutor
from deploy.agents.zenoh_session import (
    AgentNetwork,
    concrete_endpoint,
    hello_key,
    load_credentials,
    open_session,
    reply_key,
    write_credentials,
)
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.config.scenario import load_scenario
from deploy.runtime.sim_run import SimRun
from drivers.robot_descriptions import srb_parameters


@pytest.fixture(scope="module")
def run() -> Iterator[SimRun]:
    scenario = load_scenario("two_go2")
    scenario = scenario.model_copy(update={"controller": scenario.controller.model_copy(
        update={"executor": "serial"})})
    run = SimRun(scenario, CompiledCodeCache())
    yield run
    run.close()


@pytest.fixture(scope="module")
def executor(run: SimRun) -> Iterator[ZenohExecutor]:
    spec = LocalSolverSpec(run.control.settings, 2, run.control.cache)
    executor = ZenohExecutor(spec, AgentNetwork(reply_timeout_s=2.0), "two_go2")
    yield executor
    executor.close()


def _inputs(run: SimRun, t: float = 0.0):  # noqa: ANN202
    control = run.control
    measurements = [run.links.drivers[name].read() for name in control.robot_names]
    control.reset(measurements, start_s=0.0)
    return control.nmpc_inputs(t, measurements, run.simulation.mocap().latest()).inputs


def test_agents_over_zenoh_plan_what_this_process_plans(run: SimRun,
                                                        executor: ZenohExecutor) -> None:
    assert sorted(executor.hellos) == [0, 1]
    assert all(h.problem_digest == executor.digest for h in executor.hellos.values())
    team = TeamModel.from_settings(run.scenario.team_settings(), srb_parameters)
    networked = DistributedMpc(team, run.control.settings, executor=executor)
    inputs = _inputs(run)
    remote = networked.update(inputs)
    run.control.controller.reset()
    local = run.control.controller.update(inputs)
    assert remote.success and [s.status for s in remote.solves] == [
        s.status for s in local.solves]
    # The agents are fresh processes on this CPU's BLAS kernels, this process may have loaded
    # CasADi's generic ones first: equal within the cold start's tolerance, not bit for bit.
    np.testing.assert_allclose(remote.grf, local.grf, rtol=0, atol=1e-3)
    np.testing.assert_allclose(remote.consensus_trajectory, local.consensus_trajectory,
                               rtol=0, atol=1e-2)
    second = networked.update(_inputs(run, 0.05))  # warm: the agents got multipliers
    assert second.success and executor.late_replies == 0


def test_messages_not_for_the_team_are_dropped_and_counted(run: SimRun,
                                                           executor: ZenohExecutor) -> None:
    before = sum(executor.rejected.values())
    # (a peer of the team, holding its credentials, that sends what is not the team's)
    intruder = open_session([], executor.endpoints, executor.credentials)
    try:
        time.sleep(0.5)  # let the sessions meet
        intruder.put(reply_key(executor.key_prefix, 0), b"\x00garbage\xff")
        intruder.put(hello_key(executor.key_prefix, 1), wire.encode_hello(
            "another_team", 1, executor.digest, "elsewhere", 1, 0))
        deadline = time.monotonic() + 5.0
        while sum(executor.rejected.values()) < before + 2 and time.monotonic() < deadline:
            time.sleep(0.05)
    finally:
        intruder.close()
    assert sum(executor.rejected.values()) >= before + 2, executor.rejected
    assert executor.hellos[1].team == "two_go2"  # the foreign hello changed nothing
    team = TeamModel.from_settings(run.scenario.team_settings(), srb_parameters)
    assert DistributedMpc(team, run.control.settings, executor=executor).update(
        _inputs(run)).success


def test_a_forged_and_a_replayed_reply_never_reach_a_plan(run: SimRun,
                                                        executor: ZenohExecutor) -> None:
    """A well-formed reply of agent 1 put on agent 0's key is forged (a reply is bound to its
    key) and one with an old sequence is a replay: both are counted and left out, and the
    update that follows plans from the agents' own replies."""
    from core.admm.admm_executor import LocalSolveRequest
    from core.nmpc.nlp_solver import NlpSolution, SolveStats

    sizes = executor.sizes
    bogus = NlpSolution(np.full(sizes.decision, 1e3), np.zeros(sizes.constraints),
                        np.zeros(sizes.decision), SolveStats("Solve_Succeeded", True, 1, 0.001,
                                                             0.0, 0.0))
    request = LocalSolveRequest(1, np.zeros(sizes.decision), np.zeros(sizes.parameters),
                                np.zeros(sizes.decision), np.zeros(sizes.decision))
    forged_before = executor.rejected["agent not its key's"]
    late_before = executor.late_replies
    intruder = open_session([], executor.endpoints, executor.credentials)
    try:
        time.sleep(0.5)  # let the sessions meet
        intruder.put(reply_key(executor.key_prefix, 0),
                     wire.encode_reply(bogus, "two_go2", 1, executor._sequence, request))
        intruder.put(reply_key(executor.key_prefix, 1),
                     wire.encode_reply(bogus, "two_go2", 1, max(executor._sequence - 1, 0),
                                       request))
        deadline = time.monotonic() + 5.0
        while (executor.rejected["agent not its key's"] == forged_before
               or executor.late_replies == late_before) and time.monotonic() < deadline:
            time.sleep(0.05)
    finally:
        intruder.close()
    assert executor.rejected["agent not its key's"] == forged_before + 1
    assert executor.late_replies == late_before + 1
    team = TeamModel.from_settings(run.scenario.team_settings(), srb_parameters)
    plan = DistributedMpc(team, run.control.settings, executor=executor).update(_inputs(run))
    assert plan.success and np.all(np.abs(plan.grf) < 1e3)


def test_a_session_without_the_teams_credentials_reaches_nothing(
        run: SimRun, executor: ZenohExecutor, tmp_path: Path) -> None:
    """Zenoh's user/password authentication: a session with no credentials or another team's
    opens no link, so even its garbage is never heard (nothing counted), and a well-formed
    hello it sends changes nothing."""
    before, late = dict(executor.rejected), executor.late_replies
    hellos = dict(executor.hellos)
    stranger = write_credentials(tmp_path / "other_team")
    for credentials in (None, stranger):
        intruder = open_session([], executor.endpoints, credentials)
        try:
            time.sleep(0.7)  # as long as an authenticated peer needs to meet the team
            for _ in range(5):
                intruder.put(reply_key(executor.key_prefix, 0), b"\x00garbage\xff")
                intruder.put(hello_key(executor.key_prefix, 1), wire.encode_hello(
                    "two_go2", 1, executor.digest, "intruder", 1, 0))
            time.sleep(0.5)
        finally:
            intruder.close()
    assert dict(executor.rejected) == before and executor.late_replies == late
    assert {a: h.host for a, h in executor.hellos.items()} == {a: h.host
                                                               for a, h in hellos.items()}
    team = TeamModel.from_settings(run.scenario.team_settings(), srb_parameters)
    assert DistributedMpc(team, run.control.settings, executor=executor).update(
        _inputs(run)).success


def test_hand_started_agents_need_the_teams_credentials(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match="credentials_file: agents started by hand"):
        AgentNetwork(spawn_agents=False)
    credentials = write_credentials(tmp_path / "team")
    assert load_credentials(credentials.file) == credentials
    assert oct(credentials.file.stat().st_mode & 0o777) == "0o600"
    with pytest.raises(FileExistsError):
        write_credentials(credentials.file)  # never overwritten


def test_agents_that_never_come_are_reported(run: SimRun, tmp_path: Path) -> None:
    spec = LocalSolverSpec(run.control.settings, 2, run.control.cache)
    network = AgentNetwork(spawn_agents=False, start_timeout_s=1.0, key_prefix="porter/nobody",
                           credentials_file=str(write_credentials(tmp_path / "c").file))
    with pytest.raises(RuntimeError, match=r"agents \[0, 1\] did not announce themselves"):
        ZenohExecutor(spec, network, "two_go2")


def test_an_agent_holding_another_problem_is_refused(run: SimRun, tmp_path: Path) -> None:
    spec = LocalSolverSpec(run.control.settings, 2, run.control.cache)
    endpoint = concrete_endpoint("tcp/127.0.0.1:0")
    credentials = write_credentials(tmp_path / "c")
    network = AgentNetwork(listen=[endpoint], spawn_agents=False, start_timeout_s=10.0,
                           key_prefix="porter/mixed", credentials_file=str(credentials.file))
    stop = threading.Event()

    def stale_agents() -> None:  # hellos for another problem, as agents of an old config send
        time.sleep(0.5)  # the coordinator listens by then
        peer = open_session([], [endpoint], credentials)
        try:
            while not stop.is_set():
                for agent in (0, 1):
                    peer.put(hello_key("porter/mixed", agent), wire.encode_hello(
                        "two_go2", agent, "0123456789abcdef", "elsewhere", 4711, 0))
                stop.wait(0.2)
        finally:
            peer.close()

    thread = threading.Thread(target=stale_agents, daemon=True)
    thread.start()
    try:
        with pytest.raises(RuntimeError, match="holds problem 0123456789abcdef"):
            ZenohExecutor(spec, network, "two_go2")
    finally:
        stop.set()
        thread.join()


def test_a_killed_agent_is_a_failed_solve_for_its_robot_only(run: SimRun) -> None:
    spec = LocalSolverSpec(run.control.settings, 2, run.control.cache)
    executor = ZenohExecutor(spec, AgentNetwork(reply_timeout_s=0.5), "two_go2")
    try:
        team = TeamModel.from_settings(run.scenario.team_settings(), srb_parameters)
        mpc = DistributedMpc(team, run.control.settings, executor=executor)
        assert mpc.update(_inputs(run)).success
        os.kill(executor.hellos[1].pid, signal.SIGKILL)
        time.sleep(0.2)
        started = time.monotonic()
        plan = mpc.update(_inputs(run, 0.05))
        assert time.monotonic() - started < 0.5 * 2 + 1.0  # two ADMM rounds, then on
        statuses = [s.status for s in plan.solves]
        assert any("agent 1 did not answer within 0.5 s" in s for s in statuses), statuses
        assert not any("agent 0" in s for s in statuses), statuses
        assert not plan.success
    finally:
        executor.close()


def test_coordinator_free_agents_reach_the_coordinators_consensus(
        run: SimRun, executor: ZenohExecutor) -> None:
    """``topology: peer``: the agents exchange their s^i over Zenoh and each computes s-bar
    and every dual; on the same inputs they land where the coordinator over Zenoh lands (the
    same agent processes' kernels: to rounding), and agree among themselves (no warning)."""
    spec = LocalSolverSpec(run.control.settings, 2, run.control.cache)
    peers = ZenohExecutor(spec, AgentNetwork(reply_timeout_s=2.0, topology="peer"), "two_go2")
    try:
        team = TeamModel.from_settings(run.scenario.team_settings(), srb_parameters)
        coordinated = DistributedMpc(team, run.control.settings, executor=executor)
        free = PeerDistributedMpc(team, run.control.settings, peers)
        for t in (0.0, 0.05):
            inputs = _inputs(run, t)
            central, shared = coordinated.update(inputs), free.update(inputs)
            assert shared.success and not shared.warnings, shared.warnings
            np.testing.assert_allclose(shared.consensus_trajectory,
                                       central.consensus_trajectory, rtol=0, atol=1e-9)
            np.testing.assert_allclose(shared.grf, central.grf, rtol=0, atol=1e-9)
        assert peers.rejected == {} and peers.late_replies == 0
        os.kill(peers.hellos[1].pid, signal.SIGKILL)  # a dead peer: nobody can agree
        time.sleep(0.2)
        plan = free.update(_inputs(run, 0.1))
        assert not plan.success and all(not s.success for s in plan.solves)
        statuses = " ".join(s.status for s in plan.solves)
        assert "agent 1 did not answer" in statuses and "silent" in statuses, statuses
    finally:
        peers.close()

"""``porter deploy --config CONFIG [--backend hw|sim] [--yes] [--duration S] [--record LOG.mcap]``.

Builds the controller (NMPC, WBCs), starts the simulated world for ``--backend sim``, opens
the links, records the run (``deploy.recording.run_record``, backend ``hw`` or ``sim``) and runs
``deploy.runtime.loop`` (paced clock, the full sequence). Prints the pre-flight report, the
state transitions and a summary (JSON on stdout; also the log's summary metadata). Exit codes:
0 ran and sat down, 1 pre-flight failed, 2 bad config / arguments, 3 safe stop, 130 stopped by
Ctrl-C / SIGTERM (the team sat down first), 4 the operator declined to arm.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import threading
import time
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any, NamedTuple

import numpy as np
import yaml

from core.model.conventions import PAYLOAD_NAME
from deploy.cli.conventions import DIFFERS, OK, SAFE_STOP, STOPPED, Output
from deploy.compute import realtime
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.compute.cpu_meter import RunningCpu, cpu_seconds
from deploy.config.deploy_config import DeployConfig, load_deploy_config
from deploy.config.files import ConfigError
from deploy.nmpc_runtime.nmpc_process import NmpcProcess
from deploy.nmpc_runtime.nmpc_schedule import NmpcRunner, NmpcSchedule
from deploy.nmpc_runtime.nmpc_thread import NmpcThread
from deploy.recording.flight_recorder import FlightRecorder
from deploy.recording.log_format import DEPLOY_CONFIG_ATTACHMENT
from deploy.recording.run_record import default_log_path, open_run_recorder
from deploy.runtime.clock import PacedClock
from deploy.runtime.controller import TeamController
from deploy.runtime.links import TeamLinks, open_links
from deploy.runtime.loop import ControlLoop, LoopSettings
from deploy.runtime.stop_request import StopRequest
from deploy.safety.preflight import PreflightReport, evaluate
from deploy.safety.supervisor import SafetyState
from deploy.safety.watchdog import Watchdog, WatchdogSpec
from deploy.sim_backend.porter_faults import PorterFaults
from drivers.interfaces import RobotMeasurement
from drivers.link_errors import LinkMonitor

if TYPE_CHECKING:  # the robot path never imports MuJoCo: the sim backend loads on use
    from deploy.sim_backend.backend import SimBackend

SWITCH_INTERVAL_S = 2e-4


class OperatorPrompt:
    """The operator's answer from ``stream`` (read in a thread on first call, so the loop keeps
    holding the robots meanwhile): True for ``y``/``yes``, False for anything else or EOF.
    ``assume_yes`` (``--yes``) answers True at once."""

    def __init__(self, assume_yes: bool = False, stream: Any = None) -> None:
        self.stream = stream if stream is not None else sys.stdin
        self.answer: bool | None = True if assume_yes else None
        self._thread: threading.Thread | None = None

    def __call__(self) -> bool | None:
        if self._thread is None and self.answer is None:
            print("porter deploy: the team stands. Arm and start the run? [yes/no] ",
                  end="", file=sys.stderr, flush=True)
            self._thread = threading.Thread(target=self._read, daemon=True,
                                            name="porter-operator")
            self._thread.start()
        return self.answer

    def _read(self) -> None:
        line = self.stream.readline()
        self.answer = line.strip().lower() in ("y", "yes")


def run_deploy(args: argparse.Namespace) -> int:
    config, scenario = load_deploy_config(args.config)
    if args.no_record and args.backend == "hw":
        raise ConfigError("--no-record: every run on robots is recorded (allowed with "
                          "--backend sim only)")
    if not config.watchdog.enabled and args.backend == "hw":
        # the watchdog is what damps the motors when this process dies: robots never go
        # without it
        raise ConfigError(f"{args.config}: watchdog.enabled: false is refused on robots "
                          "(allowed with --backend sim only)")
    duration_s = args.duration if args.duration is not None else scenario.duration_s
    if not duration_s > 0:
        raise ConfigError(f"--duration: must be positive, got {duration_s}")
    out = Output(args)
    say = lambda text: out.progress(f"porter deploy: {text}")  # noqa: E731
    say(f"{config_name(args.config)}: scenario {scenario.name!r}, robots "
        f"{', '.join(config.robots)}, backend {args.backend}, run {duration_s:g} s")
    # probed before any process or thread exists (they would inherit the policy)
    scheduling = usable_scheduling(config, args.backend, say)
    in_process = config.nmpc.runner == "process"
    control = TeamController(scenario, CompiledCodeCache(), tick_s=1.0 / config.rates.wbc_hz,
                             build_mpc=not in_process, nmpc_shares_loop=not in_process)
    # Built before the world starts: a cold cache compiles the NLPs for minutes.
    process = (NmpcProcess(scenario, control.settings, control.cache, nice=scheduling.nmpc_nice,
                           cpus=scheduling.nmpc_cpus) if in_process else None)
    runner: NmpcRunner | None = process
    backend: SimBackend | None = None
    recorder: FlightRecorder | None = None
    links = None
    loop: ControlLoop | None = None
    watchdog: Watchdog | None = None
    stop = StopRequest()
    # The loop shares the interpreter lock with the recorder, MoCap and CAN threads (and the
    # NMPC's with ``nmpc.runner: thread``): a
    # thread that takes it keeps it up to the switch interval (5 ms by default, 2.5 WBC
    # periods) whenever the loop releases it (sleep, DDS write, BLAS); 0.2 ms bounds that wait.
    switch_interval_s = sys.getswitchinterval()
    sys.setswitchinterval(SWITCH_INTERVAL_S)
    try:
        if args.backend == "sim":
            from deploy.sim_backend.backend import SimBackend
            backend = SimBackend(config, scenario)
            say("simulated world running (MuJoCo, fakes on loopback)")
        clock: Callable[[], float] = backend.clock if backend is not None else time.monotonic
        sleep: Callable[[float], None] = (backend.clock.sleep if backend is not None
                                          else time.sleep)
        if backend is not None:
            config = backend.config  # the links to the fakes, sim.safety_overrides applied
        links = open_links(config, clock)
        if config.watchdog.enabled:
            watchdog = Watchdog(WatchdogSpec.of(
                config, config.sim.time_scale if backend is not None else 1.0,
                scheduling.loop_priority))
            say("watchdog running (damping to every robot if the loop stops)")
        if not args.no_record:
            path = (Path(args.record) if args.record
                    else default_log_path(scenario, prefix="deploy-"))
            recorder = open_run_recorder(
                path, scenario, control.settings, control.wbc_settings, args.backend,
                config.recorder, extra_attachments={DEPLOY_CONFIG_ATTACHMENT: yaml.safe_dump(
                    config.model_dump(mode="json"), sort_keys=False).encode()},
                blas_kernels=control.cache.blas_kernels().target)
            say(f"recording to {path}")
        if process is not None:
            process.clock = clock
            # warm starts back only for the log's keyframes
            process.memory_every = (None if recorder is None
                                    else recorder.settings.warm_start_every)
        if backend is not None and config.sim.faults:  # drills: faults of porter's own
            faults = PorterFaults(config.sim.faults, clock, backend.start_s)
            runner = faults.runner(runner or NmpcThread(control, clock))
            faults.recorder(recorder)
            sleep = faults.sleep(sleep)
        loop = deploy_loop(config, control, links, recorder, OperatorPrompt(args.yes), stop,
                           duration_s, clock, sleep, runner, watchdog)
        with (stop.installed(), realtime.applied(scheduling.loop_priority),
              realtime.pinned(scheduling.loop_cpus())):
            loop.run(f"start: porter deploy, scenario {scenario.name}")
    finally:
        sys.setswitchinterval(switch_interval_s)
        summary = None
        if loop is not None:
            summary = deploy_summary(loop, args, backend)
            summary.update(scheduling._asdict())
            summary["watchdog"] = {"enabled": watchdog is not None,
                                   "tripped": loop.watchdog_tripped,
                                   "priority": (scheduling.loop_priority if watchdog is not None
                                                else None)}
        if watchdog is not None:
            watchdog.disarm()
        if recorder is not None:
            recorder.close(summary)
        if links is not None:
            links.close()
        if backend is not None:
            backend.close()
        if runner is not None:
            runner.close()
        control.close()
    assert loop is not None and summary is not None
    if loop.sequence.report is not None and not loop.sequence.report.ok:
        print(loop.sequence.report.text(), file=sys.stderr)  # what to fix: even with --quiet
    out.report(json.dumps(summary, indent=2))
    out.write_json(summary)
    say(f"{loop.sequence.ended_by}; final state {loop.supervisor.state.name}")
    if summary.get("world_holds_over_4ms"):
        holds = summary["sim_ground_truth"]["holds"]
        say(f"the simulated world held the robots' states longer than 4 ms "
            f"{holds['over_4_ms']} times (longest {1e3 * holds['longest_s']:.0f} ms): this run "
            f"measured the machine's load, not porter")
    return exit_code(loop, stop)


class Scheduling(NamedTuple):
    """How porter's processes are scheduled (``deploy.compute.realtime``), as far as this
    process may: the loop's SCHED_FIFO priority and CPUs, the NMPC process's nice value and
    CPUs (None / 0: the normal policy, any CPU)."""

    loop_priority: int | None
    nmpc_nice: int
    loop_cpu: int | None
    nmpc_cpus: list[int] | None

    def loop_cpus(self) -> list[int] | None:
        return None if self.loop_cpu is None else [self.loop_cpu]


def usable_scheduling(config: DeployConfig, backend: str, say: Callable[[str], None]
                      ) -> Scheduling:
    """``rates.loop_priority``, ``nmpc.nice``, ``rates.loop_cpu`` and ``nmpc.cpus`` as far as
    this process may take them; one it may not is on robots (``hw``) a ``ConfigError`` (the
    loop's timing rests on it), in simulation a warning, and the normal policy instead."""
    wanted = Scheduling(config.rates.loop_priority, config.nmpc.nice, config.rates.loop_cpu,
                        config.nmpc.cpus)
    problems = {"loop_priority": realtime.check(wanted.loop_priority),
                "nmpc_nice": realtime.check_nice(wanted.nmpc_nice),
                "loop_cpu": realtime.check_cpus(wanted.loop_cpus(), "rates.loop_cpu"),
                "nmpc_cpus": realtime.check_cpus(wanted.nmpc_cpus, "nmpc.cpus")}
    usable = wanted._asdict()
    for field, problem in problems.items():
        if problem is None:
            continue
        if backend == "hw":
            raise ConfigError(problem)
        say(f"{problem} (simulation: normal scheduling instead)")
        usable[field] = 0 if field == "nmpc_nice" else None
    return Scheduling(**usable)


def deploy_loop(config: DeployConfig, control: TeamController, links: TeamLinks,
                recorder: FlightRecorder | None, confirm: Callable[[], bool | None],
                stop: Callable[[], bool], duration_s: float,
                clock: Callable[[], float] = time.monotonic,
                sleep: Callable[[float], None] = time.sleep,
                runner: NmpcRunner | None = None,
                watchdog: Watchdog | None = None) -> ControlLoop:
    """The control loop on the paced clock, through the deploy sequence (pre-flight, stand
    up, arm, run, sit down), the NMPC in ``runner`` (default: a thread of this process)."""
    recording = None if recorder is None else control.loop_recording(recorder)
    nmpc = NmpcSchedule(control, runner if runner is not None else NmpcThread(control, clock),
                        config.rates.nmpc_hz, clock, recording, links.force_torque,
                        decide_after_send=True)
    settings = LoopSettings(config.rates, config.safety, config.posture,
                            config.preflight.timeout_s)
    loop: ControlLoop

    def preflight(measurements: dict[str, RobotMeasurement], link_errors: dict[str, str]
                  ) -> PreflightReport:
        return evaluate(config, links, loop.limits, measurements, link_errors, links.sport_mode)

    loop = ControlLoop(control, links, settings, PacedClock(1.0 / config.rates.wbc_hz, clock,
                                                            sleep),
                       nmpc, recording, stop, duration_s, "deploy", confirm, preflight,
                       hooks=RunningCpu(lambda: loop.supervisor.state), watchdog=watchdog)
    return loop


def exit_code(loop: ControlLoop, stop: StopRequest) -> int:
    """``deploy.cli.conventions``: a failed pre-flight differs, a safe stop is itself, a stop
    request or a declined arming is the operator's."""
    if loop.sequence.report is not None and not loop.sequence.report.ok:
        return DIFFERS
    if any(t.target == SafetyState.SAFE_STOP for t in loop.supervisor.transitions):
        return SAFE_STOP
    if stop() or loop.sequence.ended_by == "the operator declined to arm":
        return STOPPED
    return OK


def config_name(path: str) -> str:
    return Path(path).name


def deploy_summary(loop: ControlLoop, args: argparse.Namespace,
                   backend: SimBackend | None) -> dict[str, Any]:
    """The run's summary: outcome, transitions, loop rates and jitter, NMPC health, payload
    progress from the MoCap, and (``--backend sim``) simulator ground truth."""
    supervisor = loop.supervisor
    run_s = None
    if SafetyState.RUNNING in loop.sequence.since:
        end = next((t.time_s for t in supervisor.transitions
                    if t.source == SafetyState.RUNNING), loop.now())
        run_s = end - loop.sequence.since[SafetyState.RUNNING]
    summary: dict[str, Any] = {
        "config": str(args.config), "backend": args.backend,
        "scenario": loop.control.scenario.name, "robots": loop.names,
        **loop.outcome(),
        "preflight": [{"item": c.item, "ok": c.ok, "detail": c.detail}
                      for c in (loop.sequence.report.checks if loop.sequence.report else [])],
        "duration_s": loop.duration_s, "run_s": run_s,
        "wbc_loop": loop.wbc_stats.summary(),
        "tick_stages_wall": loop.stages.summary(),
        "gc_pauses": loop.gc_pauses.summary(),
        "nmpc_loop": loop.nmpc.stats.summary(),
        "wbc_overruns": loop.clock.overruns,
        "time_scale": backend.config.sim.time_scale if backend is not None else 1.0,
        "payload": payload_progress(loop),
        "robot_min_height_running_m": {name: min(h) if h else None
                                       for name, h in loop.heights.items()},
    }
    if loop.recording is not None:
        summary["recorder_dropped"] = loop.recording.recorder.dropped
    summary["rejected"] = rejected_messages(loop.links)
    summary["cpu_s"] = cpu_seconds()
    # per second of the loop's clock over RUNNING: simulated seconds under --backend sim
    if isinstance(loop.hooks, RunningCpu):
        summary["cpu_per_running_s"] = loop.hooks.per_second()
    if backend is not None:
        truth = summary["sim_ground_truth"] = backend.ground_truth()
        # a world that held the robots' states > 4 ms measured the machine, not porter
        summary["world_holds_over_4ms"] = (truth or {}).get("holds", {}).get("over_4_ms")
    return _plain(summary)


def rejected_messages(links: TeamLinks) -> dict[str, dict[str, int]]:
    """Messages each link refused, by reason (malformed, foreign, frozen, ...)."""
    monitors = {name: getattr(driver, "link", None) for name, driver in links.drivers.items()}
    rejected = {name: dict(link.rejected) for name, link in monitors.items()
                if isinstance(link, LinkMonitor)}
    if links.mocap is not None:
        rejected["mocap"] = dict(links.mocap.counters.rejection_reasons)
    return rejected


def payload_progress(loop: ControlLoop) -> dict[str, Any]:
    """Payload positions [m] (MoCap) at the start and end of RUNNING, the goal, and how much
    closer to the goal it got."""
    goal = loop.control.reference.goal_m()
    ends = {key: frame.poses.get(PAYLOAD_NAME) for key, frame in loop.sequence.frames.items()}
    start, end = ends.get("start"), ends.get("end")
    result: dict[str, Any] = {"goal_m": goal, "start_m": None, "end_m": None,
                              "progress_toward_goal_m": None}
    if start is not None:
        result["start_m"] = start[0]
    if end is not None:
        result["end_m"] = end[0]
    if start is not None and end is not None:
        result["progress_toward_goal_m"] = float(
            np.linalg.norm(np.asarray(goal)[0:2] - start[0][0:2])
            - np.linalg.norm(np.asarray(goal)[0:2] - end[0][0:2]))
    return result


def _plain(value: Any) -> Any:
    """JSON-ready: arrays to lists, non-finite floats to None."""
    if isinstance(value, dict):
        return {str(k): _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, np.ndarray):
        return _plain(value.tolist())
    if isinstance(value, (float, np.floating)):
        return float(value) if math.isfinite(value) else None
    if isinstance(value, np.integer):
        return int(value)
    return value

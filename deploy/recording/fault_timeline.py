"""What was late before a safe stop: ``porter log timeline LOG --around-fault``.

For each safe stop in a flight log (an ``ERROR`` event of the safety supervisor on
``/events``), the ``window_s`` (50 ms) of run time before it, per robot:

- **held states**: runs of ticks whose logged state (``/robot/<name>/state``) did not advance
  (the same measurement time ``time_s`` as the tick before): the robot's side (the simulated
  world, a firmware, the link) sent nothing new, and the loop ran on an old state;
- **late ticks**: loop ticks that came more than 1.5 nominal periods after the one before
  (the gap between consecutive states' log times; the nominal period is the log's median);
- **the gait**: each foot's stance (1) or swing (0) at every change in the window
  (``/robot/<name>/wbc``), and the fastest joint with its speed;

and for the team, the NMPC plans (``/nmpc/update``) in the window and the one before it: late
ones (``deadline_missed``), and gaps between plans of more than 1.5 NMPC periods (skipped).

Times are run times [s]; "-0.032 s" in the text is 32 ms before the stop.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, field
from typing import Any

import numpy as np

from deploy.recording.log_reader import LogFile

__all__ = ["FaultTimeline", "RobotTimeline", "fault_timelines", "format_timelines"]

WINDOW_S = 0.05  # the "what was late in the 50 ms before it"
LATE_FACTOR = 1.5  # a gap over 1.5 nominal periods is late


@dataclass
class RobotTimeline:
    """One robot in the window before a stop: held states ``(start_s, held_s, ticks)``, late
    ticks ``(time_s, gap_s)``, stance changes ``(time_s, "1010")`` (feet FL FR RL RR) and the
    fastest joint ``(index, speed_rad_s, time_s)``."""

    robot: str
    held_states: list[tuple[float, float, int]] = field(default_factory=list)
    late_ticks: list[tuple[float, float]] = field(default_factory=list)
    stance: list[tuple[float, str]] = field(default_factory=list)
    fastest_joint: tuple[int, float, float] | None = None


@dataclass
class FaultTimeline:
    """A safe stop at ``time_s`` (``cause``: the transition's text), the window before it."""

    time_s: float
    cause: str
    window_s: float
    tick_period_s: float | None
    robots: list[RobotTimeline]
    late_plans: list[tuple[float, float]]  # (time_s, update_time_s) of plans past deadline
    plan_gaps: list[tuple[float, float]]  # (time_s, gap_s) before a plan, over 1.5 periods
    plans_in_window: int

    def to_json(self) -> dict[str, Any]:
        return asdict(self)


def fault_timelines(log: LogFile, window_s: float = WINDOW_S) -> list[FaultTimeline]:
    """One timeline per safe stop of ``log``, in time order (empty: the run had none)."""
    stops = [(item.time_s, item.message.text) for item in log.messages(["/events"])
             if item.message.source == "safety" and "-> SAFE_STOP" in item.message.text]
    if not stops:
        return []
    counts, _, _ = log.message_counts()
    robots = sorted(topic.split("/")[2] for topic in counts
                    if topic.startswith("/robot/") and topic.endswith("/state"))
    state_topics = [f"/robot/{name}/state" for name in robots]
    wbc_topics = [f"/robot/{name}/wbc" for name in robots]
    grouped = log.by_topic([*state_topics, *wbc_topics, "/nmpc/update", "/loop/timing"])
    period_s = _tick_period_s(grouped, state_topics)
    nmpc_period_s = _nmpc_period_s(grouped["/loop/timing"])
    return [_timeline(t, text, window_s, period_s, nmpc_period_s, robots, grouped)
            for t, text in stops]


def _tick_period_s(grouped: dict[str, list], topics: list[str]) -> float | None:
    gaps = [np.diff([item.time_s for item in grouped[topic]]) for topic in topics
            if len(grouped[topic]) > 2]
    return float(np.median(np.concatenate(gaps))) if gaps else None


def _nmpc_period_s(timing: list) -> float | None:
    periods = [item.message.nmpc_period_s for item in timing if item.message.nmpc_period_s > 0]
    return float(np.median(periods)) if periods else None


def _timeline(stop_s: float, cause: str, window_s: float, period_s: float | None,
              nmpc_period_s: float | None, robots: list[str],
              grouped: dict[str, list]) -> FaultTimeline:
    begin_s = stop_s - window_s
    robot_lines = []
    for name in robots:
        states = grouped[f"/robot/{name}/state"]
        # one state before the window, to see whether its first tick was already stale
        start = max(0, next((i for i, s in enumerate(states) if s.time_s >= begin_s),
                            len(states)) - 1)
        window = [s for s in states[start:] if s.time_s <= stop_s]
        line = RobotTimeline(name)
        _held_and_late(line, window, begin_s, period_s)
        _gait(line, grouped[f"/robot/{name}/wbc"], begin_s, stop_s)
        robot_lines.append(line)
    updates = grouped["/nmpc/update"]
    before = [u for u in updates if u.time_s < begin_s][-1:]
    plans = [u for u in updates if begin_s <= u.time_s <= stop_s]
    late = [(u.time_s, u.message.update_time_s) for u in plans if u.message.deadline_missed]
    gaps = []
    if nmpc_period_s is not None:
        times = [u.time_s for u in [*before, *plans]] + [stop_s]
        gaps = [(b, b - a) for a, b in zip(times, times[1:], strict=False)
                if b - a > LATE_FACTOR * nmpc_period_s]
    return FaultTimeline(stop_s, cause, window_s, period_s, robot_lines, late, gaps, len(plans))


def _held_and_late(line: RobotTimeline, window: list, begin_s: float,
                   period_s: float | None) -> None:
    run_start: float | None = None
    run_ticks = 0
    for previous, current in zip(window, window[1:], strict=False):
        gap = current.time_s - previous.time_s
        if period_s is not None and gap > LATE_FACTOR * period_s and current.time_s >= begin_s:
            line.late_ticks.append((current.time_s, gap))
        if current.message.time_s == previous.message.time_s:  # the state did not advance
            run_start = previous.time_s if run_start is None else run_start
            run_ticks += 1
            continue
        if run_start is not None:
            line.held_states.append((run_start, current.time_s - run_start, run_ticks))
        run_start, run_ticks = None, 0
    if run_start is not None and window:  # still held at the stop
        line.held_states.append((run_start, window[-1].time_s - run_start, run_ticks))
    speeds = [(float(np.max(np.abs(s.message.joint_velocity_rad_s))),
               int(np.argmax(np.abs(s.message.joint_velocity_rad_s))), s.time_s)
              for s in window if s.time_s >= begin_s and len(s.message.joint_velocity_rad_s)]
    if speeds:
        speed, joint, time_s = max(speeds)
        line.fastest_joint = (joint, speed, time_s)


def _gait(line: RobotTimeline, ticks: list, begin_s: float, stop_s: float) -> None:
    for tick in ticks:
        if tick.time_s > stop_s:
            break
        if tick.time_s < begin_s:
            continue
        pattern = "".join("1" if s > 0.5 else "0" for s in tick.message.stance)
        if not line.stance or line.stance[-1][1] != pattern:  # the first, then each change
            line.stance.append((tick.time_s, pattern))


def format_timelines(timelines: list[FaultTimeline]) -> str:
    """The timelines as text, times relative to each stop [ms]."""
    if not timelines:
        return "no safe stop in this log"
    blocks = []
    for timeline in timelines:
        t0 = timeline.time_s

        def ms(time_s: float, t0: float = t0) -> str:
            return f"{1e3 * (time_s - t0):+.0f} ms"
        period = ("-" if timeline.tick_period_s is None
                  else f"{1e3 * timeline.tick_period_s:.1f} ms")
        lines = [f"safe stop at {t0:.3f} s: {timeline.cause}",
                 f"  the {1e3 * timeline.window_s:.0f} ms before it (tick period {period}):"]
        for robot in timeline.robots:
            held = ", ".join(f"{ms(s)} for {1e3 * d:.0f} ms ({n} ticks)"
                             for s, d, n in robot.held_states) or "none"
            late = ", ".join(f"{ms(t)} ({1e3 * g:.1f} ms gap)" for t, g in robot.late_ticks)
            gait = " ".join(f"{ms(t)} {p}" for t, p in robot.stance) or "no WBC ticks"
            lines.append(f"  {robot.robot}: held states: {held}")
            lines.append(f"    late ticks: {late or 'none'}")
            lines.append(f"    stance (FL FR RL RR): {gait}")
            if robot.fastest_joint is not None:
                joint, speed, time_s = robot.fastest_joint
                lines.append(f"    fastest joint: {joint} at {speed:.1f} rad/s ({ms(time_s)})")
        late_plans = ", ".join(f"{ms(t)} ({1e3 * u:.1f} ms)" for t, u in timeline.late_plans)
        gaps = ", ".join(f"{ms(t)} ({1e3 * g:.0f} ms without a plan)" for t, g in timeline.plan_gaps)
        lines.append(f"  plans: {timeline.plans_in_window} in the window; late: "
                     f"{late_plans or 'none'}; gaps: {gaps or 'none'}")
        blocks.append("\n".join(lines))
    return "\n\n".join(blocks)

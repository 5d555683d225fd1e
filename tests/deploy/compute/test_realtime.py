"""The loop thread's real-time priority: set and restored where allowed, refused with the
setting's name where not (a child process without the privilege), and the deploy command's
policy (robots: an error; simulation: a warning and normal scheduling)."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap

import pytest

from deploy.compute import realtime

# A child process losing the privilege (``drop()``, after its imports: nobody may not read
# the interpreter's files): root becomes nobody; then no real-time priority is allowed at all
# (RLIMIT_RTPRIO 0), whoever runs the tests.
_UNPRIVILEGED = textwrap.dedent("""
    import os, resource
    def drop():
        if os.geteuid() == 0:
            os.setgid(65534)
            os.setuid(65534)
        resource.setrlimit(resource.RLIMIT_RTPRIO, (0, 0))
""")


def _child(code: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=60, cwd=os.getcwd(),
                          env={**os.environ, "PYTHONPATH": os.getcwd()}, check=False)


def test_nothing_changes_without_a_priority() -> None:
    before = os.sched_getscheduler(0), os.sched_getparam(0).sched_priority
    assert realtime.check(None) is None
    with realtime.applied(None):
        assert (os.sched_getscheduler(0), os.sched_getparam(0).sched_priority) == before


def test_the_priority_holds_inside_and_the_old_policy_returns_after() -> None:
    result = _child(textwrap.dedent("""
        import os
        from deploy.compute import realtime
        problem = realtime.check(20)
        assert os.sched_getscheduler(0) == os.SCHED_OTHER  # the probe restores
        if problem is None:
            with realtime.applied(20):
                assert os.sched_getscheduler(0) == os.SCHED_FIFO
                assert os.sched_getparam(0).sched_priority == 20
            print("applied")
        else:
            try:
                with realtime.applied(20):
                    raise SystemExit("ran without the priority")
            except realtime.RealtimePriorityError as error:
                assert str(error) == problem
            print("refused")
        assert os.sched_getscheduler(0) == os.SCHED_OTHER
        assert os.sched_getparam(0).sched_priority == 0
    """))
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() in ("applied", "refused")


def test_a_whole_process_goes_to_fifo_every_thread_or_says_why_not() -> None:
    """The sim world's priority: every thread of the process (a helper thread too), or the
    reason naming the setting; without the privilege, always the reason."""
    imports = "import os, threading\nfrom deploy.compute import realtime\n"
    code = textwrap.dedent("""
        stop = threading.Event()
        helper = threading.Thread(target=stop.wait)
        helper.start()
        problem = realtime.set_process_priority(30, "sim.world_priority")
        if problem is None:
            tasks = [int(t) for t in os.listdir("/proc/self/task")]
            policies = {os.sched_getscheduler(t) for t in tasks}
            assert len(tasks) >= 2 and policies == {os.SCHED_FIFO}, policies
            assert {os.sched_getparam(t).sched_priority for t in tasks} == {30}
            print("applied")
        else:
            print(problem)
        stop.set()
        helper.join()
    """)
    result = _child(imports + code)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "applied" or "sim.world_priority: cannot run" in result.stdout
    refused = _child(_UNPRIVILEGED + imports + "drop()\n" + code)
    assert refused.returncode == 0, refused.stderr
    assert "sim.world_priority: cannot run at SCHED_FIFO priority 30" in refused.stdout
    assert "sim.world_priority: null" in refused.stdout


def test_a_whole_process_goes_to_its_cpus_every_thread_or_says_why_not() -> None:
    """The sim world's CPUs: every thread of the process (a helper thread too) on them; a CPU
    the process may not use is refused, naming the setting and the CPUs it may use."""
    code = textwrap.dedent("""
        import os, threading
        from deploy.compute import realtime
        cpu = max(os.sched_getaffinity(0))
        stop = threading.Event()
        helper = threading.Thread(target=stop.wait)
        helper.start()
        assert realtime.set_process_cpus([cpu], "sim.world_cpus") is None
        tasks = [int(t) for t in os.listdir("/proc/self/task")]
        assert len(tasks) >= 2 and all(os.sched_getaffinity(t) == {cpu} for t in tasks)
        print(realtime.set_process_cpus([1023], "sim.world_cpus"))
        stop.set()
        helper.join()
    """)
    result = _child(code)
    assert result.returncode == 0, result.stderr
    assert "sim.world_cpus: CPU 1023 is not available to this process" in result.stdout


def test_without_the_privilege_it_is_refused_naming_the_setting() -> None:
    result = _child(_UNPRIVILEGED + textwrap.dedent("""
        import os
        from deploy.compute import realtime
        drop()
        problem = realtime.check(50)
        assert problem is not None
        print(problem)
        try:
            with realtime.applied(50):
                raise SystemExit("ran without the priority")
        except realtime.RealtimePriorityError as error:
            assert str(error) == problem
        assert os.sched_getscheduler(0) == os.SCHED_OTHER
    """))
    assert result.returncode == 0, result.stderr
    assert "rates.loop_priority: cannot run the loop at SCHED_FIFO priority 50" in result.stdout
    assert "rates.loop_priority: null" in result.stdout


def test_a_lower_nice_value_is_probed_and_refused_without_the_privilege() -> None:
    result = _child(_UNPRIVILEGED + textwrap.dedent("""
        import os
        from deploy.compute import realtime
        start = os.getpriority(os.PRIO_PROCESS, 0)
        allowed = realtime.check_nice(start - 5) is None
        assert os.getpriority(os.PRIO_PROCESS, 0) == start  # the probe restores
        drop()
        assert realtime.check_nice(start + 3) is None  # less CPU: always allowed
        problem = realtime.check_nice(start - 5)
        assert problem is not None
        try:
            realtime.set_nice(start - 5)
            raise SystemExit("took a lower nice value")
        except realtime.RealtimePriorityError as error:
            assert str(error) == problem
        realtime.set_nice(start + 3)
        assert os.getpriority(os.PRIO_PROCESS, 0) == start + 3
        print(allowed, problem)
    """))
    assert result.returncode == 0, result.stderr
    assert "nmpc.nice: cannot run the NMPC at nice" in result.stdout
    assert "set nmpc.nice: 0" in result.stdout


@pytest.mark.parametrize("backend", ["hw", "sim"])
def test_deploy_refuses_on_robots_and_warns_in_simulation(backend: str) -> None:
    result = _child(_UNPRIVILEGED + textwrap.dedent(f"""
        from deploy.cli.deploy_command import usable_scheduling
        from deploy.config.deploy_config import load_deploy_config
        from deploy.config.files import ConfigError
        config, _ = load_deploy_config("two_go2")
        # the shipped loop priority, and an NMPC nice below 0 (a robot computer's setting)
        config = config.model_copy(update={{"nmpc": config.nmpc.model_copy(update={{"nice": -10}})}})
        assert (config.rates.loop_priority, config.nmpc.nice) == (50, -10)
        drop()
        said = []
        try:
            print("scheduling", tuple(usable_scheduling(config, {backend!r}, said.append)))
        except ConfigError as error:
            print("error", error)
        print("said", said)
    """))
    assert result.returncode == 0, result.stderr
    if backend == "hw":  # the first refusal ends it
        assert result.stdout.startswith("error rates.loop_priority: cannot run the loop")
    else:
        cpus = os.sched_getaffinity(0)  # the shipped CPUs stay where this machine has them
        assert result.stdout.startswith(
            f"scheduling (None, 0, {0 if 0 in cpus else None}, {[1] if 1 in cpus else None})")
        assert result.stdout.count("(simulation: normal scheduling instead)") == 2 + len(
            {0, 1} - cpus)


@pytest.mark.parametrize("backend", ["hw", "sim"])
def test_cpus_this_process_may_not_use_are_refused_on_robots_and_left_in_simulation(
        backend: str) -> None:
    result = _child(textwrap.dedent(f"""
        import os
        from deploy.cli.deploy_command import usable_scheduling
        from deploy.config.deploy_config import load_deploy_config
        from deploy.config.files import ConfigError
        config, _ = load_deploy_config("two_go2")
        assert (config.rates.loop_cpu, config.nmpc.cpus) == (0, [1])  # the shipped ones
        os.sched_setaffinity(0, {{0}})  # as on a one-core computer
        said = []
        try:
            print("scheduling", tuple(usable_scheduling(config, {backend!r}, said.append))[2:])
        except ConfigError as error:
            print("error", error)
        print("said", said)
    """))
    assert result.returncode == 0, result.stderr
    if backend == "hw":
        assert result.stdout.startswith("error nmpc.cpus: CPU 1 is not available to this "
                                        "process (it may run on 0); name those or set "
                                        "nmpc.cpus: null")
    else:
        assert result.stdout.startswith("scheduling (0, None)")
        assert "nmpc.cpus: CPU 1 is not available" in result.stdout


def test_the_loop_and_its_helper_threads_are_pinned_inside_and_free_after() -> None:
    result = _child(textwrap.dedent("""
        import os
        from deploy.compute import realtime
        before = os.sched_getaffinity(0)
        cpu = min(before)
        assert realtime.check_cpus([cpu], "rates.loop_cpu") is None
        # a helper thread running before the block (as the MoCap client, CAN, DDS)
        import threading
        started, done, helper = threading.Event(), threading.Event(), []
        def wait():
            helper.append(threading.get_native_id())
            started.set()
            done.wait()
        threading.Thread(target=wait, daemon=True).start()
        started.wait()
        with realtime.pinned([cpu]):
            assert os.sched_getaffinity(0) == {cpu}
            assert os.sched_getaffinity(helper[0]) == {cpu}  # the whole process
        assert os.sched_getaffinity(0) == before
        assert os.sched_getaffinity(helper[0]) == before
        done.set()
        with realtime.pinned(None):
            assert os.sched_getaffinity(0) == before
        try:
            realtime.pin([4096 + cpu])  # beyond any CPU set
            raise SystemExit("pinned to a CPU that does not exist")
        except realtime.RealtimePriorityError as error:
            print(error)
        assert os.sched_getaffinity(0) == before
    """))
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("cannot run on CPUs [")

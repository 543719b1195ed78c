"""A ``drafting`` run watched from outside, for the fault tests: its handlers, workers and output seen
in /proc and its folder, and its whole process group stopped (SIGSTOP) at the moment a test names, so a
signal lands at that moment whatever the load of the machine -- and a run that ended first fails the
test instead of passing it."""

from __future__ import annotations

import os
import signal
import subprocess
import time
from pathlib import Path

import pytest


def temporaries(folder: Path) -> list[str]:
    return sorted(n for n in os.listdir(folder) if n.startswith(".drafting-tmp-")) if folder.is_dir() else []


def handlers_installed(pid: int) -> bool:
    try:
        status = Path(f"/proc/{pid}/status").read_text()
    except OSError:
        return False
    caught = int(next(l.split()[1] for l in status.splitlines() if l.startswith("SigCgt:")), 16)
    return bool(caught & (1 << (signal.SIGTERM - 1)))


def wait_for(cond, timeout: float = 60.0) -> bool:
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if cond():
            return True
        time.sleep(0.001)
    return False


def group(pgid: int) -> dict[int, str]:
    """pid -> state letter of every live process in the process group ``pgid``."""
    out = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                fields = Path(f"/proc/{entry}/stat").read_text().rsplit(") ", 1)[1].split()
            except (OSError, IndexError):
                continue
            if int(fields[2]) == pgid and fields[0] not in "ZX":
                out[int(entry)] = fields[0]
    return out


def freeze_at(p: subprocess.Popen, moment, what: str, timeout: float = 120.0) -> None:
    """Wait until ``moment()`` holds, then stop the run's process group (SIGSTOP) and return once every
    process in it has stopped and the moment still holds; if the moment passed while the stop was on its
    way, let the group go on and look again.  The test fails if the run ends first: a fault sent after the
    run has tested nothing.  The caller sends its fault, then :func:`_resume`."""
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if p.poll() is not None:
            pytest.fail(f"the run ended (exit {p.returncode}) before {what}: the fault was not tested")
        if moment():
            os.killpg(p.pid, signal.SIGSTOP)
            # a process inside a system call it cannot leave (D: fsync on a busy disk) runs no more of its
            # own code: it stops when the call returns (seen to take over 120 s under load)
            assert wait_for(lambda: all(s in "TD" for s in group(p.pid).values()), 120), \
                f"the group did not stop: {group(p.pid)}"
            if p.poll() is None and moment():
                return
            resume(p)
        time.sleep(0.001)
    pytest.fail(f"{what} did not come within {timeout:.0f} s")


def signal_at(p: subprocess.Popen, moment, what: str, sig: int) -> tuple[str, str, list[int]]:
    """``sig`` sent to the run at ``moment`` (:func:`_freeze_at`); its output once it has ended, and the
    workers it had when signalled."""
    try:
        freeze_at(p, moment, what)
        workers = children(p.pid)
        p.send_signal(sig)
        resume(p)
        stdout, stderr = p.communicate(timeout=120)
    except BaseException:
        end(p)
        raise
    return stdout, stderr, workers


def end(p: subprocess.Popen) -> None:
    """After a test that failed on the way: the run's whole group killed (stopped or not) and reaped."""
    try:
        os.killpg(p.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass
    p.wait()


def resume(p: subprocess.Popen) -> None:
    try:
        os.killpg(p.pid, signal.SIGCONT)
    except ProcessLookupError:              # nothing left in the group
        pass


def maps(pid: int) -> str:
    try:
        return Path(f"/proc/{pid}/maps").read_text()
    except OSError:
        return ""


def children(pid: int) -> list[int]:
    try:
        return [int(c) for c in Path(f"/proc/{pid}/task/{pid}/children").read_text().split()]
    except OSError:
        return []


def gone(pid: int) -> bool:
    try:
        return Path(f"/proc/{pid}/stat").read_text().split(") ", 1)[1].startswith("Z")   # a zombie is gone
    except OSError:
        return True

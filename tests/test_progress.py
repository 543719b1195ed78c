"""The progress bar (issue 22): on a terminal a long job shows it from the start and a shorter one once it
has run a second; a pipe or a file never sees it."""

from __future__ import annotations

import io

from drafting.app import progress
from drafting.app.progress import Progress


class Tty(io.StringIO):
    def isatty(self):
        return True


def test_a_short_job_shows_its_bar_once_it_has_run_a_second(monkeypatch):
    clock = [0.0]
    monkeypatch.setattr(progress.time, "perf_counter", lambda: clock[0])
    stream = Tty()
    bar = Progress(10, "sweep", stream)
    bar.update(2)
    assert stream.getvalue() == ""                        # under a second: nothing yet
    clock[0] = 1.5
    bar.update(3)
    assert "\rsweep [" in stream.getvalue() and " 30.0 % (1.5 s)" in stream.getvalue()
    bar.finish()
    assert stream.getvalue().endswith("100.0 % (1.5 s)\n")


def test_a_job_done_within_a_second_and_a_pipe_show_nothing(monkeypatch):
    clock = [0.0]
    monkeypatch.setattr(progress.time, "perf_counter", lambda: clock[0])
    quick, pipe = Tty(), io.StringIO()
    a, b = Progress(10, "csv", quick), Progress(10 ** 6, "sweep", pipe)
    for done in range(11):
        a.update(done)                                    # ten updates within 0.9 s
        b.update(done * 10 ** 5)                          # a long job, but into a pipe
        clock[0] += 0.09
    a.finish()
    clock[0] += 5.0
    b.finish()
    assert quick.getvalue() == "" and pipe.getvalue() == ""

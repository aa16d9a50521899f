"""Where the report's time goes: with FORMSOLVE_REPORT_TIMES=FILE set, each
process (the report and its --render subprocess) appends to FILE one line
per stage, "<process> <stage> <seconds>", the seconds since its previous
line (the first since this module was imported, right after the launcher
started Python). benchmarks/report_time.sh reads them. Unset: nothing."""
import os
import time

FILE = os.environ.get("FORMSOLVE_REPORT_TIMES")
_last = time.perf_counter()


def lap(process, stage):
    """The time since the last lap of this process, as stage's."""
    global _last
    if not FILE:
        return
    now = time.perf_counter()
    with open(FILE, "a") as out:
        out.write(f"{process}\t{stage}\t{now - _last:.4f}\n")
    _last = time.perf_counter()  # the writing itself is not the next stage's

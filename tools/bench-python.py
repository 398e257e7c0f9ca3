#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
"""Measures the Python module (docs/python.md): the cost of one short simulate call over the
core's own time, called directly and on a thread of its own that Ctrl+C stops (alternated in
one process), two simulate calls on two threads against the same two one after the other (best of
--repeats, alternated), and how long Ctrl+C takes to stop a long map. Run with Debian's Python:
    PYTHONPATH=build/python /usr/bin/python3 tools/bench-python.py
"""

import argparse
import os
import signal
import threading
import time

import grazelab as gl

RUN = dict(m2=0.3, glo=0.4, perturb=(0, 0, 0, -0.02), trust="off")


def sequential(contacts):
    started = time.perf_counter()
    gl.simulate(**RUN, contacts=contacts)
    gl.simulate(**RUN, contacts=contacts)
    return time.perf_counter() - started


def threaded(contacts):
    started = time.perf_counter()
    threads = [threading.Thread(target=gl.simulate, kwargs=dict(RUN, contacts=contacts))
               for _ in range(2)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    return time.perf_counter() - started


SHORT = dict(glo=0.5, perturb=(0, 0, 0, -0.05), contacts=10, trust="off")


def per_call(calls, **extra):
    """Microseconds per call of a 10-contact simulate, and the core's own (its timing.seconds,
    the least of the calls: what the core takes without the module)."""
    started = time.perf_counter()
    for _ in range(calls):
        gl.simulate(**SHORT, **extra)
    seconds = (time.perf_counter() - started) / calls
    core = min(gl.simulate(**SHORT, **extra).timing.seconds for _ in range(200))
    return seconds * 1e6, core * 1e6


def interrupt_latency(delay):
    timer = threading.Timer(delay, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    started = time.perf_counter()
    try:
        gl.map(x="u1:-1.5:1.5:400", y="v1:-1:1:400", contacts=4000)
    except KeyboardInterrupt:
        pass
    timer.join()
    return time.perf_counter() - started - delay


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--contacts", type=int, default=400000)
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    direct, threaded_calls = [], []
    for _ in range(args.repeats):
        direct.append(per_call(5000))
        # a progress callback sends the same call to a thread of its own
        threaded_calls.append(per_call(1000, progress=lambda fraction, line: None))
    direct_us, core_us = min(direct)
    threaded_us, _ = min(threaded_calls)
    print(f"simulate(contacts=10): {direct_us:.1f} us a call called directly, {threaded_us:.1f} us "
          f"on a thread of its own; the core's own {core_us:.1f} us: "
          f"{direct_us - core_us:.1f} us over the core (best of {args.repeats})")
    one, two = [], []
    for _ in range(args.repeats):
        one.append(sequential(args.contacts))
        two.append(threaded(args.contacts))
    print(f"two simulate({args.contacts} contacts): one after the other {min(one):.3f} s, "
          f"on two threads {min(two):.3f} s: ratio {min(two) / min(one):.2f} "
          f"(median {sorted(two)[len(two) // 2] / sorted(one)[len(one) // 2]:.2f}; "
          f"{os.cpu_count()} cores)")
    latencies = [interrupt_latency(0.5) for _ in range(3)]
    print(f"Ctrl+C during a long map: stopped {max(latencies) * 1000:.0f} ms after the signal "
          f"(worst of 3)")


if __name__ == "__main__":
    main()

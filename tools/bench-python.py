#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
"""Measures the Python module (docs/python.md): two simulate calls on two threads against the
same two one after the other (best of --repeats, alternated in one process), and how long
Ctrl+C takes to stop a long map. Run with Debian's Python:
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

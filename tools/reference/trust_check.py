#!/usr/bin/env python3
"""Check the `trust` estimate of `grazelab-cli simulate` against the true error, measured
with the independent reference (reference_sim.py, exact decimal inputs).

For each canonical case of compare.py the true errors are formed exactly as the CLI defines
its estimates: the final state, each component against its own scale (its largest size at
the events and at the end, floored at 1e-3 of the positions' or velocities' scale), and the
worst contact time in units of T2. The estimate passes when the true error is at most 10x
the estimate, and (runs whose 1e-16 nudge stays below 1e6 growth) the estimate is at most
1000x the true error. Exit 0 = all pass.

    python3 trust_check.py --cli build/app/grazelab-cli/grazelab-cli [--precision long]
"""
import argparse
import os
import sys
from concurrent.futures import ThreadPoolExecutor

from mpmath import mp, mpf

import compare

OPTIMISM = 10     # the true error may be at most this many times the estimate
PESSIMISM = 1000  # the estimate may be at most this many times the true error (regular runs)


def true_errors(ref_out, cli_out):
    """(state error at the end, worst contact time error / T2) of the CLI run."""
    mp.dps = 40
    to = compare.to_mpf
    model = ref_out["model"]
    T2, w2, gap = to(model["T2"]), to(model["omega2"]), to(model["gap"])
    ref_events, cli_events = ref_out["events"], cli_out["events"]
    if len(ref_events) != len(cli_events):
        return mpf("inf"), mpf("inf")
    time_error = mpf(0)
    for a, b in zip(ref_events, cli_events):
        time_error = max(time_error, abs(to(a["t"]) - to(b["t"])) / T2)
    keys = ("u1", "u2", "v1", "v2")
    size = {k: mpf(0) for k in keys}
    size["u2"] = abs(gap)
    states = [ref_out["initial"], ref_out["final"]]
    for e in ref_events:
        states.append({"u1": e["u1"], "u2": e["u2"], "v1": e["v1_pre"], "v2": e["v2_pre"]})
        states.append({"u1": e["u1"], "u2": e["u2"], "v1": e["v1_pre"], "v2": e["v2_post"]})
    for s in states:
        for k in keys:
            size[k] = max(size[k], abs(to(s[k])))
    positions = max(size["u1"], size["u2"])
    velocities = max(size["v1"], size["v2"], w2 * positions)
    state_error = mpf(0)
    for k in keys:
        floor = (positions if k[0] == "u" else velocities) / 1000
        scale = max(size[k], floor)
        state_error = max(state_error, abs(to(ref_out["final"][k]) - to(cli_out["final"][k])) / scale)
    return state_error, time_error


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cli", default=compare.DEFAULT_CLI)
    parser.add_argument("--precision", default="double", choices=["double", "long", "quad"])
    parser.add_argument("--trust", default="auto", choices=["auto", "full"])
    parser.add_argument("--case", default=None)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--timeout", type=float, default=120.0)
    args = parser.parse_args()
    if os.path.isdir(args.cli):
        args.cli = os.path.join(args.cli, "grazelab-cli")
    dps = 50 if args.precision == "quad" else 40
    ref_flags = ["--dps", str(dps), "--digits", "40"]
    selected = [c for c in compare.cases() if args.case is None or args.case in c[0]]

    def one(case):
        name, case_args = case
        common = ["simulate"] + case_args + ["--contacts", str(compare.CONTACTS), "--format", "json"]
        ref_cmd = [sys.executable, os.path.join(compare.HERE, "reference_sim.py")] + common + ref_flags
        ref_out, ref_err, _ = compare.run_json(ref_cmd, args.timeout)
        probe_out, _, _ = compare.run_json(ref_cmd + ["--nudge", "1e-16"], args.timeout)
        cli_out, cli_err, _ = compare.run_json(
            [args.cli] + common + ["--precision", args.precision, "--trust", args.trust],
            args.timeout)
        return name, ref_out, ref_err, probe_out, cli_out, cli_err

    with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        results = list(pool.map(one, selected))

    failures = 0
    header = "%-36s %9s %9s %9s %9s %8s %11s  %s" % (
        "case", "state", "est", "t/T2", "est", "regular", "verdict", "result")
    print(header)
    print("-" * len(header))
    floor = mpf(2) ** -113 if args.precision == "quad" else (
        mpf(2) ** -64 if args.precision == "long" else mpf(2) ** -53)
    for name, ref_out, ref_err, probe_out, cli_out, cli_err in results:
        if ref_err or cli_err:
            failures += 1
            print("%-36s FAIL %s" % (name, ref_err or cli_err))
            continue
        trust = cli_out["trust"]
        est_state = mpf(str(trust["estimated_state_error"]))
        est_time = mpf(str(trust["estimated_time_error"]))
        state, time_error = true_errors(ref_out, cli_out)
        # regular: a 1e-16 nudge of the start grows less than 1e6 times (not chaotic here)
        nudge_state, _ = true_errors(ref_out, probe_out) if probe_out else (mpf("inf"), 0)
        regular = nudge_state < mpf("1e-10")
        problems = []
        for label, true, est in (("state", state, est_state), ("time", time_error, est_time)):
            if not true <= OPTIMISM * est:
                problems.append("%s: true %s > %dx estimate" % (label, mp.nstr(true, 2), OPTIMISM))
            if regular and est > PESSIMISM * max(true, floor):
                problems.append("%s: estimate %s > %dx true" % (label, mp.nstr(est, 2), PESSIMISM))
        failures += bool(problems)
        print("%-36s %9s %9s %9s %9s %8s %11s  %s" % (
            name, mp.nstr(state, 2), mp.nstr(est_state, 2), mp.nstr(time_error, 2),
            mp.nstr(est_time, 2), "yes" if regular else "no", trust["verdict"],
            "FAIL " + "; ".join(problems) if problems else "PASS"))
    print("-" * len(header))
    print("%d case(s), %d failure(s); precision %s, --trust %s; true error <= %dx estimate, "
          "estimate <= %dx true on regular runs" % (len(results), failures, args.precision,
                                                    args.trust, OPTIMISM, PESSIMISM))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Compare `grazelab-cli simulate` with the independent mpmath reference (reference_sim.py).

    python3 compare.py --cli /path/to/grazelab-cli      # exit 0 if every case passes

For each canonical case both programs get the same command-line arguments plus
`--contacts 50 --format json`; the reference also gets `--double-inputs`, so that it
simulates exactly the binary64 inputs the C++ program reads, with the exactly 1:2 resonant
k2 of those inputs (the C++ core keeps omega1 = 2 omega2 exactly; `--k2-from-double` gives
the reference the binary64 k2 instead, a chain detuned by ~1e-16, see README.md).
Over the first 50 events the script reports

- t:    max |t_cli - t_ref| / T2
- pos:  max |u_cli - u_ref| / ps,  ps = max(gap, max |u| over the reference events)
- vel:  max |v_cli - v_ref| / (omega_slow * ps)   (v1_pre, v2_pre and v2_post)
- type: number of events whose type differs (and a count mismatch if the two programs do
        not produce the same number of events within the first 50)
- amplif: how much the motion itself amplifies a 1e-16 nudge of the initial state (a second
        reference run with `--nudge 1e-16`)
and PASS if every error is <= --tol (default 1e-10) with no type or count mismatch;
PASS~ if an error is above --tol but below --sensitivity-factor (100) times the effect of
the 1e-16 nudge at that event: no binary64 program can do better there (docs/model.md
section 6); `--strict` turns PASS~ into FAIL. Cases run with --t-end also compare the
`final` state. Exit status: 0 if every case is PASS or PASS~, 1 otherwise (including a
missing or failing CLI, or a failing reference run).

The reference is the same mathematics computed exactly in extended precision (40 digits),
not a second double-precision program, so the errors shown are the C++ program's own.
"""

import argparse
import decimal
import json
import os
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

from mpmath import mp, mpf

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import reference_sim as ref  # noqa: E402

DEFAULT_CLI = "/work/main/build/app/grazelab-cli/grazelab-cli"
CONTACTS = 50
NUDGE = mpf("1e-16")  # relative size of the sensitivity probe (about one binary64 ulp)


def num(x):
    """A binary64 value as a 17-digit string, so both programs read the same double."""
    return repr(float(x))


def model_args(m1="1", m2="0.5", k1="1", gap="1", branch="upper", k2=None):
    args = ["--m1", m1, "--m2", m2, "--k1", k1, "--gap", gap]
    args += ["--k2", k2] if k2 is not None else ["--branch", branch]
    return args


def chain_of(m1="1", m2="0.5", k1="1", gap="1", branch="upper", k2=None):
    mp.dps = 40
    return ref.Chain(mpf(m1), mpf(m2), mpf(k1), mpf(gap), k2=None if k2 is None else mpf(k2),
                     branch=branch)


def perturbed_glo(name, lam, du1=0, du2=0, dv1=0, dv2=0, t_end_periods=None, **model):
    """A GLO_lambda start with a perturbation given relative to the gap and to w2 * gap."""
    ch = chain_of(**model)
    d = float(ch.gap)
    vs = float(ch.w[1]) * d
    args = model_args(**model) + ["--glo", lam]
    if any((du1, du2, dv1, dv2)):
        args += ["--perturb", ",".join(num(x) for x in (du1 * d, du2 * d, dv1 * vs, dv2 * vs))]
    if t_end_periods is not None:
        args += ["--t-end", num(t_end_periods * float(ch.T2))]
    return name, args


def cases():
    out = [
        perturbed_glo("upper glo0.5 dv2=-1e-3", "0.5", dv2=-1e-3),
        perturbed_glo("upper glo0.5 du2=-1e-3 (no contact)", "0.5", du2=-1e-3,
                      t_end_periods=20),
        perturbed_glo("upper glo0.25 du1,dv2=1e-3,-1e-3", "0.25", du1=1e-3, dv2=-1e-3),
        perturbed_glo("upper glo1.2 du2,dv2=-1e-4,+1e-2", "1.2", du2=-1e-4, dv2=1e-2),
        perturbed_glo("lower glo0.5 dv2=-1e-3", "0.5", dv2=-1e-3, branch="lower"),
        perturbed_glo("lower glo0.9 du2,dv2=-1e-4,+3e-2", "0.9", du2=-1e-4, dv2=3e-2,
                      branch="lower"),
        perturbed_glo("m2/m1=1e-4 glo0.5 dv2=-1e-3", "0.5", dv2=-1e-3, m2="1e-4"),
        perturbed_glo("m2/m1=1e-4 lower glo0.5 dv2=-1e-3", "0.5", dv2=-1e-3, m2="1e-4",
                      branch="lower"),
        perturbed_glo("gap=1e-9 glo0.5 dv2=-1e-3", "0.5", dv2=-1e-3, gap="1e-9"),
        perturbed_glo("gap=1e6 glo0.5 dv2=-1e-3", "0.5", dv2=-1e-3, gap="1e6"),
        perturbed_glo("sticking start glo1.5", "1.5"),
        perturbed_glo("near grazing dv2=-1e-9 vs", "0.5", dv2=-1e-9),
        perturbed_glo("near grazing dv2=-1e-12 vs", "0.5", dv2=-1e-12),
        perturbed_glo("lower near grazing dv2=-1e-12 vs", "0.5", dv2=-1e-12, branch="lower"),
    ]
    ch = chain_of()
    out.append(("1IPP T=0.95 T2", model_args() + ["--onepp", num(0.95 * float(ch.T2))]))
    out.append(("detuned k2=0.45 state", model_args(k2="0.45")
                + ["--state", "0.2,0.5,0.1,0.8"]))
    return out


def run_json(command, timeout):
    started = time.perf_counter()
    try:
        proc = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, "timeout after %g s" % timeout, timeout
    except OSError as error:
        return None, str(error), 0.0
    seconds = time.perf_counter() - started
    if proc.returncode != 0:
        return None, "exit %d: %s" % (proc.returncode, proc.stderr.strip()[:200]), seconds
    try:
        return json.loads(proc.stdout, parse_float=decimal.Decimal), None, seconds
    except ValueError as error:
        return None, "bad JSON: %s" % error, seconds


def to_mpf(x):
    if x is None:
        return mpf("nan")
    return mpf(str(x))


def event_errors(a_out, b_out, T2, ps, vs):
    """Per-event normalised differences of run b against run a, over the first CONTACTS
    events (plus the final state when run a stopped at t-end).

    Returns a list of (label, {"t", "pos", "vel"}, same_type) and the two event counts.
    """
    a_events = a_out["events"][:CONTACTS]
    b_events = b_out.get("events", [])[:CONTACTS]
    rows = []
    for i in range(min(len(a_events), len(b_events))):
        a, b = a_events[i], b_events[i]
        rows.append((i, {
            "t": abs(to_mpf(b.get("t")) - to_mpf(a["t"])) / T2,
            "pos": max(abs(to_mpf(b.get(k)) - to_mpf(a[k])) for k in ("u1", "u2")) / ps,
            "vel": max(abs(to_mpf(b.get(k)) - to_mpf(a[k]))
                       for k in ("v1_pre", "v2_pre", "v2_post")) / vs,
        }, a["type"] == b.get("type")))
    if a_out["reference"]["termination"] == "t_end":
        a, b = a_out["final"], b_out.get("final", {})
        rows.append(("final", {
            "t": abs(to_mpf(b.get("t")) - to_mpf(a["t"])) / T2,
            "pos": max(abs(to_mpf(b.get(k)) - to_mpf(a[k])) for k in ("u1", "u2")) / ps,
            "vel": max(abs(to_mpf(b.get(k)) - to_mpf(a[k])) for k in ("v1", "v2")) / vs,
        }, True))
    return rows, len(a_events), len(b_events)


def compare_case(ref_out, probe_out, cli_out, tol, factor):
    """Error figures of one case and its verdict.

    probe_out is the reference nudged by NUDGE (binary64 round-off size): its distance to
    the reference, times `factor`, is what a correct binary64 program may be off by where
    the motion amplifies errors (docs/model.md section 6). Returns (err, n, amplification,
    strict_ok, problems) with problems empty if the case passes within that allowance.
    """
    mp.dps = 40
    model = ref_out["model"]
    T2, w2, gap = to_mpf(model["T2"]), to_mpf(model["omega2"]), to_mpf(model["gap"])
    ref_events = ref_out["events"][:CONTACTS]
    ps = max([gap] + [abs(to_mpf(e[k])) for e in ref_events for k in ("u1", "u2")])
    vs = w2 * ps
    rows, n_ref, n_cli = event_errors(ref_out, cli_out, T2, ps, vs)
    probe_rows, _, n_probe = event_errors(ref_out, probe_out, T2, ps, vs)
    sens = {label: (errs, same) for label, errs, same in probe_rows}
    err = {"t": mpf(0), "pos": mpf(0), "vel": mpf(0)}
    amplification = mpf(0)
    problems = []
    strict_ok = True
    types = 0
    beyond = None  # first event where a round-off-sized nudge changes the event type
    worst = {}  # kind -> (excess ratio, value, event, allowance) of the worst violation
    for label, errs, same in rows:
        probe_errs, probe_same = sens.get(label, (None, False))
        if beyond is None and not probe_same:
            beyond = label
        if not same:
            types += 1
            strict_ok = False
            if probe_same:
                problems.append("type mismatch at event %s" % label)
        for kind, value in errs.items():
            err[kind] = max(err[kind], value)
            if not value <= tol:  # also catches nan
                strict_ok = False
                allowed = factor * probe_errs[kind] if probe_same else mpf("inf")
                if not value <= allowed:
                    ratio = value / allowed if allowed > 0 else mpf("inf")
                    if mp.isnan(ratio) or kind not in worst or ratio > worst[kind][0]:
                        worst[kind] = (ratio, value, label, allowed)
            if probe_same:
                amplification = max(amplification, probe_errs[kind] / NUDGE)
    for kind, (ratio, value, label, allowed) in worst.items():
        problems.append("%s err %s at event %s (round-off allows %s)" % (
            kind, mp.nstr(value, 3), label, mp.nstr(allowed, 3)))
    if n_ref != n_cli:
        strict_ok = False
        if beyond is None or n_probe == n_ref:
            problems.append("event count ref %d cli %d" % (n_ref, n_cli))
    return err, len(rows), types, amplification, beyond, strict_ok, problems[:3]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cli", default=DEFAULT_CLI, help="path of grazelab-cli")
    parser.add_argument("--tol", type=float, default=1e-10)
    parser.add_argument("--strict", action="store_true",
                        help="--tol is binding even where the motion itself amplifies "
                             "round-off beyond it (see README.md)")
    parser.add_argument("--sensitivity-factor", type=float, default=100.0,
                        help="allowance: this many times the effect of a 1e-16 nudge")
    parser.add_argument("--dps", type=int, default=40, help="reference precision")
    parser.add_argument("--samples", type=int, default=2000, help="reference scan density")
    parser.add_argument("--exact-inputs", action="store_true",
                        help="reference reads the decimal inputs exactly instead of the "
                             "binary64 values the CLI sees")
    parser.add_argument("--k2-from-double", action="store_true",
                        help="reference uses the binary64 k2 of the design formula (a chain "
                             "detuned by ~1e-16) instead of the exactly resonant k2")
    parser.add_argument("--ref-only", action="store_true",
                        help="only run the reference (no CLI): timing and event counts")
    parser.add_argument("--case", default=None, help="run only cases whose name contains this")
    parser.add_argument("--cli-precision", default=None, choices=["double", "long", "quad"],
                        help="pass --precision to the CLI (quad: use with --exact-inputs, "
                             "--tol 1e-28 and --skip-chaotic)")
    parser.add_argument("--skip-chaotic", action="store_true",
                        help="leave out the cases whose 1e-16 nudge grows beyond 1e6 (the "
                             "sticking start): no fixed tolerance applies to them")
    parser.add_argument("--jobs", type=int, default=1, help="cases run in parallel")
    parser.add_argument("--timeout", type=float, default=60.0, help="per program run, s")
    args = parser.parse_args()

    if os.path.isdir(args.cli):  # a CMake target directory: the binary is inside
        args.cli = os.path.join(args.cli, "grazelab-cli")
    if not args.ref_only and not os.access(args.cli, os.X_OK):
        print("compare.py: CLI not found or not executable: %s" % args.cli)
        return 1

    ref_flags = ["--dps", str(args.dps), "--samples", str(args.samples), "--digits",
                 str(min(args.dps, 40))]
    if not args.exact_inputs:
        ref_flags.append("--double-inputs")
    if args.k2_from_double:
        ref_flags.append("--k2-from-double")
    selected = [c for c in cases() if args.case is None or args.case in c[0]]
    if args.skip_chaotic:
        selected = [c for c in selected if "sticking start" not in c[0]]

    def one(case):
        name, case_args = case
        common = ["simulate"] + case_args + ["--contacts", str(CONTACTS), "--format", "json"]
        ref_cmd = [sys.executable, os.path.join(HERE, "reference_sim.py")] + common + ref_flags
        ref_out, ref_err, ref_s = run_json(ref_cmd, args.timeout)
        if args.ref_only:
            return name, ref_out, ref_err, ref_s, None, None, None, 0.0
        probe_out, probe_err, _ = run_json(ref_cmd + ["--nudge", mp.nstr(NUDGE, 5)],
                                           args.timeout)
        if ref_err is None and probe_err is not None:
            ref_err = "sensitivity probe: " + probe_err
        cli_extra = ["--precision", args.cli_precision] if args.cli_precision else []
        cli_out, cli_err, cli_s = run_json([args.cli] + common + cli_extra, args.timeout)
        return name, ref_out, ref_err, ref_s, probe_out, cli_out, cli_err, cli_s

    started = time.perf_counter()
    with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        results = list(pool.map(one, selected))

    failures = 0
    relaxed = 0
    header = "%-36s %4s %9s %9s %9s %4s %8s %6s %6s  %s" % (
        "case", "n", "t/T2", "pos", "vel", "type", "amplif", "ref s", "cli s", "result")
    print(header)
    print("-" * len(header))
    for name, ref_out, ref_err, ref_s, probe_out, cli_out, cli_err, cli_s in results:
        if ref_err is not None:
            failures += 1
            print("%-36s FAIL reference: %s" % (name, ref_err))
            continue
        if args.ref_only:
            types = {}
            for e in ref_out["events"]:
                types[e["type"]] = types.get(e["type"], 0) + 1
            print("%-36s %4d %9s %9s %9s %4s %8s %6.2f %6s  %s" % (
                name, len(ref_out["events"]), "", "", "", "", "", ref_s, "",
                " ".join("%s:%d" % kv for kv in sorted(types.items()))))
            continue
        if cli_err is not None:
            failures += 1
            print("%-36s %4s %9s %9s %9s %4s %8s %6.2f %6.2f  FAIL cli: %s" % (
                name, "", "", "", "", "", "", ref_s, cli_s, cli_err))
            continue
        err, n, types, amplification, beyond, strict_ok, problems = compare_case(
            ref_out, probe_out, cli_out, args.tol, args.sensitivity_factor)
        if strict_ok:
            status = "PASS"
        elif problems or args.strict:
            status = "FAIL " + "; ".join(problems or ["errors above --tol (--strict)"])
            failures += 1
        else:
            status = "PASS~ (above tol, within %g x round-off effect)" % args.sensitivity_factor
            relaxed += 1
        if beyond is not None:
            status += " [nudge changes event %s]" % beyond
        print("%-36s %4d %9s %9s %9s %4d %8s %6.2f %6.2f  %s" % (
            name, n, mp.nstr(err["t"], 2), mp.nstr(err["pos"], 2), mp.nstr(err["vel"], 2),
            types, mp.nstr(amplification, 2), ref_s, cli_s, status))
    print("-" * len(header))
    print("%d case(s), %d failure(s), %d PASS~; tolerance %g; reference dps %d, %s, %s; %.1f s"
          % (len(results), failures, relaxed, args.tol, args.dps,
             "exact decimal inputs" if args.exact_inputs else "binary64 inputs",
             "k2 from binary64" if args.k2_from_double else "exactly resonant k2",
             time.perf_counter() - started))
    if not args.ref_only:
        print("amplif = largest growth of a 1e-16 nudge of the initial state over the run; "
              "PASS~ = error above tol but below %g x that effect (docs/model.md section 6)"
              % args.sensitivity_factor)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

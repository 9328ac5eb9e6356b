#!/usr/bin/env python3
"""Stage breakdown of a `perf record --call-graph dwarf` profile of `penner uniformize`.

    perf record -F 499 --call-graph dwarf,16384 -o P.data -- \
        target/release/penner uniformize M.obj --targets M-targets.json --precision 256 -o M.json
    python3 benches/peers/conformal_ideal_delaunay/profile_stages.py P.data

Each sample goes to the stage whose function is on its call stack (reading, Euclidean
flips, f64 solve, the replay of the input's Euclidean flips to T0 on MPFR/intervals,
refinement, certificate, claim writing). GMP's assembly kernels have no unwind tables, so
DWARF unwinding stops in them (about a fifth of the samples); as the stages run one after
another on the main thread, such a sample is given the stage of the nearest attributed
sample in time on the same thread. Both tallies are printed. Layout is not a stage of
`uniformize` without `--svg`.
"""
import sys, subprocess, collections
# Classify each perf sample by the stage function found in its call stack (outermost match wins).
STAGES = [  # (stage, substrings of a frame's symbol)
    ("claim writing", ["ClosedOutcome::claim", "Certification::claim", "certificate_report::write_claim", "claim_form::"]),
    ("certificate", ["certificate::certify_after_flips", "certificate::certify_near",
                     "prove::certify_after_flips", "prove::certify_near"]),
    ("refinement", ["refine::refine_with_flips", "refine::refine_problem", "certificate::prove_on",
                    "prove::prove_on", "prove::refine_and_certify"]),
    ("replay of the input to T0 (MPFR/intervals)", ["closed::input_on_t0", "closed::input_metric_on_t0", "input_metric::", "closed::t0_delaunay_for_input", "Surface>::lengths", "surface::Surface::lengths"]),
    ("Euclidean flips", ["algorithms::flip_to_delaunay::flip_to_delaunay"]),
    ("f64 solve", ["newton::uniformize_with_progress"]),
    ("reading", ["input::load_flip_case", "uniformize::read_targets", "into_surface"]),
]
data = sys.argv[1]
out = subprocess.run(["perf", "script", "-i", data, "-F", "period,ip,sym", "--no-demangle"] if False else ["perf", "script", "-i", data, "-F", "tid,time,ip,sym"], capture_output=True, text=True).stdout
samples = out.split("\n\n")
cnt = collections.Counter(); total = 0; seq = []
unk_leaf = collections.Counter()
for s in samples:
    lines = [l.strip() for l in s.strip().split("\n") if l.strip()]
    if not lines: continue
    head = lines[0].split()
    tid, t = head[0], float(head[1].rstrip(":"))
    frames = lines[1:]
    if not frames: continue
    total += 1
    syms = [f.split(" ", 1)[1] if " " in f else f for f in frames]
    stage = None
    # walk from the root (last frame) to the leaf; the first stage-marker from the root decides,
    # except that claim/certificate/refinement markers are nested in prove_on/certify_solution
    found = set()
    for sym in syms:
        for st, keys in STAGES:
            if any(k in sym for k in keys):
                if st == "Euclidean flips" and "flip_to_delaunay::flip_to_delaunay_" in sym:
                    continue
                found.add(st)
    for st, _ in STAGES:  # priority order
        if st in found:
            stage = st; break
    if stage == "refinement" and "certificate" in found: stage = "certificate"
    if stage is None:
        joined = " ".join(syms)
        if "cli::uniformize::run" in joined or "cli::main" in joined:
            stage = "other (inside the command)"
        else:
            stage = "unattributed (stack not unwound to a stage)"
            unk_leaf[syms[0][:80]] += 1
    cnt[stage] += 1
    seq.append((tid, t, stage))
print(data, "samples", total)
for st, c in cnt.most_common():
    print("  %-45s %5d  %5.1f%%" % (st, c, 100.0 * c / total))
print("  top leaves of unattributed:", unk_leaf.most_common(8))

# Stages run one after another: give each unattributed sample the stage of the nearest
# attributed sample in time on the same thread.
import bisect
by = collections.defaultdict(list)
for tid, t, st in seq:
    if not st.startswith("unattributed"):
        by[tid].append((t, st))
for v in by.values(): v.sort()
cnt2 = collections.Counter()
for tid, t, st in seq:
    if st.startswith("unattributed") and by[tid]:
        v = by[tid]; i = bisect.bisect_left(v, (t, ""))
        cand = [v[j] for j in (i - 1, i) if 0 <= j < len(v)]
        st = min(cand, key=lambda x: abs(x[0] - t))[1]
    cnt2[st] += 1
print("  threads:", collections.Counter(x[0] for x in seq).most_common(4))
print("  with unattributed samples given the stage running at their time:")
order = [x[0] for x in STAGES[::-1]] + ["other (inside the command)", "unattributed (stack not unwound to a stage)"]
for st in order:
    if cnt2[st]:
        print("  %-45s %5d  %5.1f%%" % (st, cnt2[st], 100.0 * cnt2[st] / total))

"""The analysis of bench/mumps.py's rows: power-law fits of memory, fill and flops
against the number of equations N, the memory a run will need (predicted before it starts),
the largest mesh within 20 GB, the extrapolation to 1e7-1e8 equations on 16-64 ranks, and
the fragment doc/bench/mumps.md. Rows are dicts with the columns of bench_mumps.HEADER."""
import numpy as np

GB20_MB = 20.0 * 1024
# the fits start at the 1e5 size (99 372 equations): below it the program's fixed ~50 MB
# hides the growth
FIT_FROM = 9e4
CONFIGS = (("CHOLMOD", 1, 1), ("CHOLMOD", 2, 1), ("MUMPS", 1, 1), ("MUMPS", 1, 2))
GROWTH = 1.2  # memory exponent assumed when one smaller size only has been run
NAN = float("nan")
EFFICIENCY = 0.5  # parallel efficiency assumed on 16-64 ranks (not measured)


def fit(n, y):
    """(p, a) of y ~ a n^p by least squares on log-log; None with fewer than 2 points."""
    ok = [(a, b) for a, b in zip(n, y) if b == b and b > 0]
    if len(ok) < 2 or len({a for a, _ in ok}) < 2:
        return None
    p, la = np.polyfit(np.log([a for a, _ in ok]), np.log([b for _, b in ok]), 1)
    return float(p), float(np.exp(la))


def solve_for(f, y):
    """N at which the power law f = (p, a) reaches y."""
    return (y / f[1]) ** (1.0 / f[0])


def done(rows, problem, solver, threads, ranks, n_from=FIT_FROM):
    return [r for r in rows if r["problem"] == problem and r["solver"] == solver
            and r["threads"] == threads and r["ranks"] == ranks and r["status"] == "completed"
            and r["equations"] >= n_from]


def predicted_total_mb(rows, run):
    """Memory [MB, all ranks] the run `run` will need: the power law of the same problem and
    configuration over the smaller sizes run (from 1e4), or the one smaller size scaled as
    N^GROWTH; nan when none has been run."""
    sel = [r for r in done(rows, run["problem"], run["solver"], run["threads"], run["ranks"],
                           0) if r["equations"] < run["equations"]]
    sel = [r for r in sel if r["peak_mb_total"] == r["peak_mb_total"]]
    if not sel:
        return float("nan")
    big = [r for r in sel if r["equations"] >= FIT_FROM]
    f = fit([r["equations"] for r in big], [r["peak_mb_total"] for r in big])
    last = max(sel, key=lambda r: r["equations"])
    if f and f[0] > 0:
        # from the largest size run, with the fitted exponent but never below 1 (the
        # coefficient of a fit with a smaller exponent would not go with exponent 1)
        return last["peak_mb_total"] * (run["equations"] / last["equations"]) ** max(f[0], 1.0)
    return last["peak_mb_total"] * (run["equations"] / last["equations"]) ** GROWTH


def g(x, fmt=".3g"):
    return "-" if x != x or x == "" else format(x, fmt)


def run_table(rows):
    L = ["| problem | equations | solver, ordering | threads × ranks | status | "
         "time/increment [s] | factorisation, all [s] | peak MB per rank | factor entries | "
         "flops (one factorisation) | load | final |", "|" + "---|" * 12]
    for r in rows:
        ranks = str(r.get("peak_mb_ranks", "")).replace(";", " / ") or g(r["peak_mb_per_rank"], ".0f")
        status = r["status"] + (f" ({r['note']})" if r.get("note") else "")
        L.append(f"| {r['problem']} | {r['equations']} | {r['solver']}, {r.get('ordering') or '-'} "
                 f"| {r['threads']} × {r['ranks']} | {status} | {g(r['time_per_increment_s'])} | "
                 f"{g(r['t_factorisation_s'])} | {ranks} | {g(r['nnz_factor'])} | "
                 f"{g(r['flops'])} | {g(r.get('load_run', float('nan')), '.1f')} | "
                 f"{r.get('final') or 'no'} |")
    return L


def not_run(rows):
    """'problem N: configurations' for each problem and size (of any problem) lacking rows."""
    sizes = sorted({r["equations"] for r in rows})
    out = []
    for prob in dict.fromkeys(r["problem"] for r in rows):
        for n in sizes:
            have = {(r["solver"], r["threads"], r["ranks"]) for r in rows
                    if r["problem"] == prob and r["equations"] == n}
            lack = [f"{s} {t} × {k}" for s, t, k in CONFIGS if (s, t, k) not in have]
            if lack:
                out.append(f"{prob} at {n} equations: " + (
                    "all four" if len(lack) == len(CONFIGS) else ", ".join(lack)))
    return out


def estimate_table(rows):
    L = ["| equations | ranks | est. factor entries INFOG(3) | est. flops RINFOG(1) | "
         "est. MB largest rank INFOG(16) | est. MB all ranks INFOG(17) | MB used, largest rank "
         "INFOG(21) |", "|---|---|---|---|---|---|---|"]
    for r in rows:
        if r["solver"] == "MUMPS" and r["problem"] == "elastic" and r["status"] == "completed":
            L.append(f"| {r['equations']} | {r['ranks']} | {g(r['est_factor_entries'])} | "
                     f"{g(r['est_flops'])} | {g(r['est_mb_rank'], '.0f')} | "
                     f"{g(r.get('est_mb_total', float('nan')), '.0f')} | "
                     f"{g(r['mumps_mb_rank'], '.0f')} |")
    return L


def extrapolated(n, top):
    return f"{n:.2e}" + (" (extrapolated)" if n > top else " (within the sizes run)")


def fit_table(rows):
    L = ["| problem | solver | threads × ranks | sizes fitted | memory (all ranks) ~ N^p | "
         "equations in 20 GB (all ranks) | equations with 20 GB per rank |",
         "|---|---|---|---|---|---|---|"]
    for prob in sorted({r["problem"] for r in rows}):
        for solver, threads, ranks in CONFIGS:
            sel = done(rows, prob, solver, threads, ranks)
            ft = fit([r["equations"] for r in sel], [r["peak_mb_total"] for r in sel])
            fr = fit([r["equations"] for r in sel], [r["peak_mb_per_rank"] for r in sel])
            if not ft or not fr:
                L.append(f"| {prob} | {solver} | {threads} × {ranks} | {len(sel)} | - | not "
                         "fitted: needs two sizes from 1e5 equations up | - |")
                continue
            top = max(r["equations"] for r in sel)
            nt, nr = solve_for(ft, GB20_MB), solve_for(fr, GB20_MB)
            L.append(f"| {prob} | {solver} | {threads} × {ranks} | {len(sel)} | {ft[0]:.2f} | "
                     f"{extrapolated(nt, top)} | {extrapolated(nr, top)} |")
    # MUMPS's own estimate of its memory (the factor and its work space, no model): the
    # bound a model partitioned among the ranks would approach
    for ranks in (1, 2):
        sel = done(rows, "elastic", "MUMPS", 1, ranks)
        ft = fit([r["equations"] for r in sel], [r["est_mb_total"] for r in sel])
        fr = fit([r["equations"] for r in sel], [r["est_mb_rank"] for r in sel])
        if ft and fr:
            top = max(r["equations"] for r in sel)
            nt, nr = (solve_for(f, GB20_MB) for f in (ft, fr))
            L.append(f"| MUMPS's estimate, INFOG(17) / INFOG(16): factor only | MUMPS | 1 × "
                     f"{ranks} | {len(sel)} | {ft[0]:.2f} | {extrapolated(nt, top)} | "
                     f"{extrapolated(nr, top)} |")
    return L


def extrapolation(rows):
    """Lines of the 1e7-1e8 section, or [] without two MUMPS sizes >= FIT_FROM."""
    mum = done(rows, "elastic", "MUMPS", 1, 1)
    n = [r["equations"] for r in mum]
    fe = fit(n, [r["est_factor_entries"] for r in mum])
    ff = fit(n, [r["est_flops"] for r in mum])
    # the replicated model: what a rank holds beside MUMPS's own memory
    fm = fit(n, [r["peak_mb_per_rank"] - r["mumps_mb_rank"] for r in mum])
    timed = [r for r in done(rows, "dp_footing", "MUMPS", 1, 1) + mum
             if r["t_factorisation_s"] > 0 and r["factorisations"] > 0]
    if not (fe and ff and fm and timed):
        return []
    top = max(timed, key=lambda r: (share_known(r), r["equations"]))
    rate_wall = top["est_flops"] * top["factorisations"] / top["t_factorisation_s"]
    # on a loaded machine the run had a share of a core only: its CPU time over its wall time
    share = cpu_share(top)
    rate = rate_wall / share
    mb_per_entry = float(np.median([r["est_mb_rank"] * 1e6 / r["est_factor_entries"]
                                    for r in mum]))
    L = ["", "**Extrapolation to 1e7–1e8 equations on 16–64 ranks** (on paper). From MUMPS's "
         f"own analysis estimates on 1 rank over {len(mum)} sizes from {min(n):.0e} to "
         f"{max(n):.1e} equations: factor entries ~ N^{fe[0]:.2f}, flops ~ N^{ff[0]:.2f} "
         "(2D nested dissection predicts N log N and N^1.5); MUMPS's memory estimate is "
         f"{mb_per_entry:.1f} bytes per factor entry (INFOG(16) over INFOG(3), median), shared "
         f"evenly by the ranks; the flop rate {rate:.2e} flop/s per rank is the one of the "
         f"largest 1-rank MUMPS run{' with its CPU time recorded' if share_known(top) else ''} "
         f"({top['problem']}, {top['equations']} equations, load "
         f"{top.get('load_run', NAN):.1f}: {rate_wall:.2e} flop/s of wall time"
         + (f", divided by the share of a core the run had, its CPU time over its wall time, "
            f"{share:.2f}" if share < 1 else "") + ") and the parallel efficiency on 16–64 ranks "
         f"is assumed {EFFICIENCY:.0%}, not measured. Today every rank also holds the whole "
         f"model (mesh, Gauss-point states: measured peak minus MUMPS's own memory, "
         f"~ N^{fm[0]:.2f}; in runs older than the division of the stiffness assembly among "
         "the ranks, see each row's commit, also the whole assembled matrix); the last column "
         "adds it, which a partitioned model would remove (doc/mpi.md).", "",
         "| equations | factor entries | flops | ranks | factor GB per rank | factorisation [s] "
         "| GB per rank with the whole model on each |", "|---|---|---|---|---|---|---|"]
    for neq in (1e7, 3e7, 1e8):
        ent, fl, model = fe[1] * neq ** fe[0], ff[1] * neq ** ff[0], fm[1] * neq ** fm[0]
        for p in (16, 64):
            share = ent * mb_per_entry / p / 1e9
            L.append(f"| {neq:.0e} | {ent:.2e} | {fl:.2e} | {p} | {share:.1f} | "
                     f"{fl / (p * rate * EFFICIENCY):.3g} | {share + model / 1024:.1f} |")
    return L


def share_known(r):
    return r.get("cpu_s", NAN) == r.get("cpu_s", NAN)


def cpu_share(r):
    """CPU time over wall time of a 1-thread run (1 if not recorded), at most 1."""
    cpu, total = r.get("cpu_s", NAN), r.get("total_s", NAN)
    return min(1.0, cpu / total) if cpu == cpu and total == total and total > 0 else 1.0


def fragment(rows, wall=None):
    dates = sorted(str(r.get("date", "")) for r in rows if r.get("date"))
    span = f"Measured {dates[0]} to {dates[-1]}" if dates else ""
    not_final = sum(1 for r in rows if r["status"] == "completed" and r.get("final") != "yes")
    L = ["## Distributed solve: MUMPS against CHOLMOD (`tools/pecplas_py/bench/mumps.py`)", "",
         "Q8 plane strain, half strip footing 10 m × 5 m: `elastic` (linear, the steps of "
         "tools/pecplas_py/decks/make_default_deck.py: 6 increments) and `dp_footing` "
         "(Drucker–Prager, "
         "geostatic stress then 300 kPa in 2 increments, full Newton). CHOLMOD on 1 and 2 "
         "threads; MUMPS (LDL^T, distributed assembled input) on 1 and 2 MPI ranks of 1 "
         "thread, every rank holding the whole model (doc/mpi.md). Time per increment = "
         "(total − read+setup) / increments; 'factorisation, all' sums every factorisation of "
         "the run. Peak memory is the resident high-water mark (VmHWM) of each rank, largest "
         "first. Load = mean number of runnable tasks on the 2 cores during the run; a timing "
         f"at load > 2 is not final ({not_final} of the completed runs here). Sizes run one at "
         "a time, smallest first; a run predicted not to fit in the memory available is "
         f"skipped. {span}. Data: `mumps.csv`.", ""]
    L += run_table(rows)
    missing = not_run(rows)
    if missing:
        L += ["", "Not run in this series: " + "; ".join(missing) + "."]
    L += ["", "**MUMPS's own estimates** (analysis, `elastic`; the footing has the same "
          "pattern):", ""] + estimate_table(rows)
    L += ["", "**Largest mesh within 20 GB** (power law of the measured peak memory against N "
          "over the completed sizes from 1e5 equations up, solved for 20 GB = "
          "20 480 MB; beyond the largest size run it is an extrapolation):", ""]
    L += fit_table(rows)
    L += extrapolation(rows)
    return "\n".join(L) + "\n"

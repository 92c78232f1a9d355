"""Tables, plot and recommendations of the accuracy-cost study from
results.csv (called by `run --analyse`).

Writes next to results.csv:
  accuracyCost.png    |error| against core-seconds per particle per D/U_ref,
                      one panel per problem, one marker per sweep, one
                      colour per surface treatment (fluidStencil; ghostCells
                      as first written, ghostShear mirrored; the
                      periodic-suspension tutorials' coupling, ghostShear
                      viscous + ghostCutCells solidFraction; each also with
                      the constraint inside two PIMPLE outer correctors), the
                      Pareto front of each (no run of that treatment both
                      cheaper and more accurate)
  table.md            every run: settings, error, wall, core-seconds, memory
  recommendations.md  the cheapest measured run within 1, 3 and 10 % per
                      problem and treatment, and the observed orders of
                      convergence
"""
import csv
import math
import os
import sys

PROBLEMS = {
    "fixedSphere": "fixed sphere, Re = 100: C_D against Clift et al.",
    "terminalRe": "settling sphere, Ga = 70, m = 2: Re_t against 71.36",
    "tenCateE2": "ten Cate E2: u_max against 0.05718 m/s",
    "tenCateE2bounce": "E2's bounce on the floor: rebound height against 80 sub-steps",
}
TUTORIAL = "ghostCells+ghostShearviscous+ghostCutCellssolidFraction"
TREATMENTS = {"fluidStencil": "tab:blue",
              # ghost cells as first written (ghostShear mirrored: fluid through
              # the bodies, found 2026-12-02)
              "ghostCells": "tab:red",
              # the constraint after each of 2 PIMPLE outer correctors (--outer 2)
              "ghostCells+nOuterCorrectors2": "tab:green",
              # the periodic-suspension tutorials' coupling (after the fix)
              TUTORIAL: "tab:purple",
              TUTORIAL + "+nOuterCorrectors2": "tab:orange"}
# How the legend names them
LABELS = {"ghostCells": "ghostCells (mirrored, before)",
          "ghostCells+nOuterCorrectors2": "ghostCells (mirrored) + 2 outer correctors",
          TUTORIAL: "tutorials' coupling (viscous + solidFraction)",
          TUTORIAL + "+nOuterCorrectors2": "tutorials' coupling + 2 outer correctors"}
MARKERS = {"resolution": "o", "time step": "s", "tolerance": "^", "surface points": "D",
           "sub-steps": "v"}


def load(path):
    rows = [r for r in csv.DictReader(open(path))]
    for r in rows:
        r["treatment"] = r.get("treatment") or "fluidStencil"
        for k in ("resolution", "cfl", "tolerance", "spacing", "subSteps", "cells", "dt",
                  "time_units", "value", "reference", "error_percent", "wall_s", "core_s",
                  "peak_rss_MiB", "core_s_per_time_unit", "overlap_D", "granular_s",
                  "fluid_s", "dlmfd_s"):
            try:
                r[k] = float(r[k])
            except (KeyError, TypeError, ValueError):
                r[k] = None
    # The bounce: error against the run with the most sub-steps
    bounce = [r for r in rows if r["problem"] == "tenCateE2bounce" and r["value"] is not None]
    if bounce:
        ref = max(bounce, key=lambda r: r["subSteps"])
        for r in bounce:
            r["reference"] = ref["value"]
            r["error_percent"] = 100 * (r["value"] - ref["value"]) / ref["value"]
    return rows


def measured(rows, problem, treatment=None):
    return [r for r in rows if r["problem"] == problem and r["core_s"] is not None
            and r["error_percent"] is not None
            and (treatment is None or r["treatment"] == treatment)]


def pareto(rs):
    """Runs that no other run beats in both cost and |error|"""
    front = []
    for r in sorted(rs, key=lambda r: (r["core_s_per_time_unit"], abs(r["error_percent"]))):
        if not front or abs(r["error_percent"]) < abs(front[-1]["error_percent"]):
            front.append(r)
    return front


def settings(r):
    if r["treatment"].startswith("ghostCells"):
        return f"{r['treatment']}, D/dx {r['resolution']:g}, CFL {r['cfl']:g}, sub-steps {r['subSteps']:g}"
    return (f"fluidStencil, D/dx {r['resolution']:g}, CFL {r['cfl']:g}, tol {r['tolerance']:g}, "
            f"spacing {r['spacing']:g}, sub-steps {r['subSteps']:g}")


def order(points):
    """Least-squares slope of log|e| against log h"""
    pts = [(math.log(h), math.log(abs(e))) for h, e in points if e]
    if len(pts) < 2:
        return None
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    sxx = sum((x - mx) ** 2 for x, _ in pts)
    return sum((x - mx) * (y - my) for x, y in pts) / sxx if sxx else None


def orders(rows):
    out = []
    for p, t in ((p, t) for p in ("fixedSphere", "terminalRe", "tenCateE2") for t in TREATMENTS):
        rs = measured(rows, p, t)
        res = [r for r in rs if r["sweep"] == "resolution"]
        if len(res) >= 2:
            # Error against the reference, h = 1/N
            s = order([(1 / r["resolution"], r["error_percent"]) for r in res])
            out.append((p, t, "space", s, len(res),
                        ", ".join(f"D/dx {r['resolution']:g}: {r['error_percent']:+.2f} %"
                                  for r in sorted(res, key=lambda r: r["resolution"]))))
        steps = [r for r in rs if r["sweep"] == "time step"]
        if not steps:
            continue
        # The time-step sweep and the base run it varies (same resolution,
        # tolerance, spacing)
        ts = [r for r in rs if r["resolution"] == steps[0]["resolution"]
              and r["tolerance"] == steps[0]["tolerance"] and r["spacing"] == steps[0]["spacing"]]
        ts = sorted({r["cfl"]: r for r in ts}.values(), key=lambda r: r["cfl"])
        if len(ts) >= 3:
            # Differences from the smallest step: the time error alone
            finest = ts[0]
            s = order([(r["cfl"], r["value"] - finest["value"]) for r in ts[1:]])
            out.append((p, t, "time", s, len(ts),
                        ", ".join(f"CFL {r['cfl']:g}: {r['error_percent']:+.2f} %" for r in ts)))
    return out


def plot(rows, png):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit("analyse.py: matplotlib is missing (etc/debianPackages: python3-matplotlib)")
    probs = [p for p in PROBLEMS if measured(rows, p)]
    fig, axes = plt.subplots(1, len(probs), figsize=(4.2 * len(probs), 3.8), squeeze=False)
    for ax, p in zip(axes[0], probs):
        for t, colour in TREATMENTS.items():
            rs = measured(rows, p, t)
            if not rs:
                continue
            for sweep, mk in MARKERS.items():
                pts = [r for r in rs if r["sweep"] == sweep]
                if pts:
                    ax.plot([r["core_s_per_time_unit"] for r in pts],
                            [max(abs(r["error_percent"]), 1e-3) for r in pts], mk, mfc="none",
                            color=colour, label=f"{LABELS.get(t, t)}: {sweep}")
            front = pareto(rs)
            ax.plot([r["core_s_per_time_unit"] for r in front],
                    [max(abs(r["error_percent"]), 1e-3) for r in front], "-", color=colour,
                    lw=0.8, label=f"{LABELS.get(t, t)}: Pareto front")
        for lvl in (1, 3, 10):
            ax.axhline(lvl, color="0.8", lw=0.6, zorder=0)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("core-seconds per particle per D/U_ref")
        ax.set_ylabel("|error| [%]")
        ax.set_title(PROBLEMS[p], fontsize=8)
        ax.legend(fontsize=5)
    fig.tight_layout()
    fig.savefig(png, dpi=100)


def table(rows, md):
    with open(md, "w") as f:
        f.write("| problem | treatment | sweep | D/dx | CFL | tolerance | spacing | sub-steps | cells | value |"
                " error [%] | wall [s] | core-s | core-s per D/U_ref | peak RSS [MiB] |"
                " granular [s] | note |\n")
        f.write("|" + "---|" * 17 + "\n")
        for r in sorted(rows, key=lambda r: (list(PROBLEMS).index(r["problem"]), r["treatment"],
                                             r["sweep"],
                                             r["resolution"] or 0, r["cfl"] or 0,
                                             r["tolerance"] or 0, r["spacing"] or 0,
                                             r["subSteps"] or 0)):
            g = lambda k, fmt="{:g}": "" if r.get(k) is None else fmt.format(r[k])
            f.write(f"| {r['problem']} | {r['treatment']} | {r['sweep']} | {g('resolution')} | {g('cfl')} |"
                    f" {g('tolerance')} | {g('spacing')} | {g('subSteps')} |"
                    f" {g('cells', '{:.0f}')} | {g('value', '{:.5g}')} |"
                    f" {g('error_percent', '{:+.2f}')} | {g('wall_s', '{:.0f}')} |"
                    f" {g('core_s', '{:.0f}')} | {g('core_s_per_time_unit', '{:.3g}')} |"
                    f" {g('peak_rss_MiB', '{:.0f}')} | {g('granular_s', '{:.3g}')} |"
                    f" {r.get('note') or ''} |\n")


def recommendations(rows, md):
    with open(md, "w") as f:
        f.write("| problem | target | cheapest measured run within it | error [%] |"
                " core-s per particle per D/U_ref | peak RSS [MiB] |\n|---|---|---|---|---|---|\n")
        for p, t in ((p, t) for p in ("fixedSphere", "terminalRe", "tenCateE2") for t in TREATMENTS):
            rs = measured(rows, p, t)
            if not rs:
                continue
            for lvl in (1, 3, 10):
                ok = [r for r in rs if abs(r["error_percent"]) <= lvl]
                if ok:
                    r = min(ok, key=lambda r: r["core_s_per_time_unit"])
                    f.write(f"| {p} | {lvl} % | {settings(r)} | {r['error_percent']:+.2f} |"
                            f" {r['core_s_per_time_unit']:.3g} | {r['peak_rss_MiB']:.0f} |\n")
                else:
                    best = min(rs, key=lambda r: abs(r["error_percent"]), default=None)
                    f.write(f"| {p} | {lvl} % | none measured (best "
                            f"{best['error_percent']:+.2f} % at {settings(best)}) | | | |\n"
                            if best else f"| {p} | {lvl} % | no run | | | |\n")
        f.write("\n| problem | treatment | order in | observed order | runs | errors |\n"
                "|---|---|---|---|---|---|\n")
        for p, t, kind, s, n, detail in orders(rows):
            f.write(f"| {p} | {t} | {kind} | {'' if s is None else f'{s:.2f}'} | {n} | {detail} |\n")


def main(path):
    here = os.path.dirname(path)
    rows = load(path)
    plot(rows, os.path.join(here, "accuracyCost.png"))
    table(rows, os.path.join(here, "table.md"))
    recommendations(rows, os.path.join(here, "recommendations.md"))
    print(open(os.path.join(here, "recommendations.md")).read())

"""Plot, tables and targets of the accuracy-cost study from results.csv
(called by `run --analyse`).

Writes next to results.csv:
  accuracyCost.png  one panel per problem: |error| against core-seconds per
                    unit of the problem's time, one series (marker and line)
                    per sweep: resolution, time step, refining mesh,
                    sub-steps; each point labelled with what changed
  table.md          every run: settings, cells, value, error, wall,
                    core-seconds, memory, phase split
  targets.md        per problem, the cheapest measured run within 10, 5 and
                    2 % (its D/dx, mesh, time step and core-hours per unit
                    of time), and the observed orders of convergence
With --documents (run --analyse --documents) it also writes targets.md's
table into doc/07-accuracy-and-cost.md, between the lines
<!-- accuracyCost: targets --> and <!-- accuracyCost: end -->.
"""
import csv
import glob
import math
import os
import sys

PROBLEMS = {
    "fixedSphereRe20": "fixed sphere, Re 20: C_D",
    "fixedSphereRe100": "fixed sphere, Re 100: C_D",
    "fixedCubeRe100": "fixed cube (face on), Re 100: C_D",
    "terminalRe": "settling sphere, Ga 70, m 2: Re_t",
    "tenCateE2": "ten Cate E2: u_max",
    "frozenCubeArray": "frozen cube array, phi 0.2, Re 20: F",
    "cubeSuspension": "cube suspension, phi 0.2, Ga 70: Re",
    "tenCateE2bounce": "E2's bounce: rebound (against 80 sub-steps)",
}
SERIES = {"resolution": ("o", "tab:blue"), "time step": ("s", "tab:orange"),
          "refining mesh": ("^", "tab:green"), "sub-steps": ("v", "tab:purple")}
TARGETS = (10, 5, 2)
NUMBERS = ("levels", "resolution", "cfl", "subSteps", "cells", "dt", "time_units", "value",
           "reference", "error_percent", "wall_s", "core_s", "peak_rss_MiB",
           "core_s_per_time_unit", "overlap_D", "fluid_s", "dlmfd_s", "granular_s")


def load(path):
    rows = list(csv.DictReader(open(path)))
    for r in rows:
        for k in NUMBERS:
            try:
                r[k] = float(r[k])
            except (KeyError, TypeError, ValueError):
                r[k] = None
    # The bounce: its error against the run with the most sub-steps
    bounce = [r for r in rows if r["problem"] == "tenCateE2bounce" and r["value"] is not None]
    if bounce:
        ref = max(bounce, key=lambda r: r["subSteps"])
        for r in bounce:
            r["reference"] = ref["value"]
            r["error_percent"] = 100 * (r["value"] - ref["value"]) / ref["value"]
    return rows


def measured(rows, problem):
    return [r for r in rows if r["problem"] == problem and r["core_s"] is not None
            and r["error_percent"] is not None]


def step_label(r):
    """The time step as the study set it"""
    if r["problem"] == "cubeSuspension":
        return f"t_g/{r['cfl']:g}"
    return f"CFL {r['cfl']:g}"


def point_label(r):
    if r["sweep"] == "time step":
        return step_label(r)
    if r["sweep"] == "sub-steps":
        return f"{r['subSteps']:g}"
    return f"{r['resolution']:g}"


def mesh_label(r):
    if r["mesh"] == "adaptive":
        return f"refining ({r['levels']:g} levels)"
    if r["mesh"] == "refineHexMesh":
        return "split once around the body"
    return r["mesh"]


def plot(rows, png):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import matplotlib.ticker
    except ImportError:
        sys.exit("analyse.py: matplotlib is missing (etc/debianPackages: python3-matplotlib)")
    probs = [p for p in PROBLEMS if measured(rows, p)]
    if not probs:
        sys.exit("analyse.py: no measured run in results.csv")
    ncol = min(4, len(probs))
    nrow = math.ceil(len(probs) / ncol)
    fig, axes = plt.subplots(nrow, ncol, figsize=(4.0 * ncol, 3.6 * nrow), squeeze=False)
    for ax in axes.flat[len(probs):]:
        ax.axis("off")
    for ax, p in zip(axes.flat, probs):
        rs = measured(rows, p)
        unit = rs[0].get("time_unit") or "unit"
        for sweep, (mk, colour) in SERIES.items():
            pts = [r for r in rs if r["sweep"] == sweep]
            if sweep == "time step" and pts:
                # The base run (of the resolution series) belongs to it too
                pts += [r for r in rs if r["sweep"] == "resolution"
                        and (r["resolution"], r["mesh"]) == (pts[0]["resolution"], pts[0]["mesh"])]
            if not pts:
                continue
            key = (lambda r: r["cfl"]) if sweep == "time step" else \
                (lambda r: r["subSteps"]) if sweep == "sub-steps" else (lambda r: r["resolution"])
            pts = sorted({point_label(r) if sweep != "time step" else step_label(r): r
                          for r in pts}.values(), key=key)
            xs = [r["core_s_per_time_unit"] for r in pts]
            ys = [max(abs(r["error_percent"]), 1e-3) for r in pts]
            label = {"resolution": "resolution D/dx", "time step": "time step",
                     "refining mesh": "refining mesh, D/dx finest", "sub-steps": "sub-steps per contact"}[sweep]
            ax.plot(xs, ys, "-" + mk, color=colour, mfc="none", lw=0.8, label=label)
            for r, x, y in zip(pts, xs, ys):
                if sweep == "time step" and r["sweep"] != "time step":
                    continue    # the base, labelled in its own series
                ax.annotate(step_label(r) if sweep == "time step" else point_label(r), (x, y),
                            textcoords="offset points", xytext=(4, 3), fontsize=6, color=colour)
        for lvl in TARGETS:
            ax.axhline(lvl, color="0.85", lw=0.6, zorder=0)
        ax.set_xscale("log")
        ax.set_yscale("log")
        plain = matplotlib.ticker.FormatStrFormatter("%g")
        ax.yaxis.set_major_formatter(plain)
        ax.yaxis.set_minor_formatter(plain)
        ax.set_xlabel(f"core-seconds per {unit}", fontsize=8)
        ax.set_ylabel("|error| [%]", fontsize=8)
        ax.tick_params(labelsize=7)
        ax.set_title(PROBLEMS[p], fontsize=8)
        ax.legend(fontsize=6, loc="best")
    fig.suptitle("dlmfdFoam (ghost cells, ghostShear link): error against cost, serial runs on one core",
                 fontsize=9)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def table(rows, md):
    with open(md, "w") as f:
        f.write("| problem | sweep | mesh | D/dx | time step | sub-steps | cells | value | error [%] |"
                " wall [s] | core-s | core-s per time unit | peak RSS [MiB] | fluid / DLM/FD / granular [s] |"
                " note |\n")
        f.write("|" + "---|" * 15 + "\n")
        for r in sorted(rows, key=lambda r: (list(PROBLEMS).index(r["problem"]), r["sweep"],
                                             r["resolution"] or 0, r["cfl"] or 0, r["subSteps"] or 0)):
            def g(k, fmt="{:g}"):
                return "" if r.get(k) is None else fmt.format(r[k])
            split = "" if r.get("fluid_s") is None else \
                f"{r['fluid_s']:.0f} / {r['dlmfd_s']:.0f} / {r['granular_s']:.1f}"
            f.write(f"| {r['problem']} | {r['sweep']} | {mesh_label(r)} | {g('resolution')} |"
                    f" {step_label(r) if r.get('cfl') is not None else ''} | {g('subSteps')} |"
                    f" {g('cells', '{:.0f}')} | {g('value', '{:.5g}')} |"
                    f" {g('error_percent', '{:+.2f}')} | {g('wall_s', '{:.0f}')} |"
                    f" {g('core_s', '{:.0f}')} | {g('core_s_per_time_unit', '{:.3g}')}"
                    f" per {r.get('time_unit') or ''} |"
                    f" {g('peak_rss_MiB', '{:.0f}')} | {split} | {r.get('note') or ''} |\n")


def order(points):
    """Least-squares slope of log|e| against log h"""
    pts = [(math.log(h), math.log(abs(e))) for h, e in points if e]
    if len(pts) < 2:
        return None
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    sxx = sum((x - mx) ** 2 for x, _ in pts)
    return sum((x - mx) * (y - my) for x, y in pts) / sxx if sxx else None


def targets_table(rows):
    """The cheapest measured run within each target, per problem"""
    lines = ["| case | target | cheapest measured run within it: D/dx, mesh, time step | its error [%] |"
             " core-hours per unit of time |", "|---|---|---|---|---|"]
    for p in PROBLEMS:
        if p == "tenCateE2bounce":
            continue
        rs = measured(rows, p)
        if not rs:
            continue
        unit = rs[0].get("time_unit") or ""
        for lvl in TARGETS:
            ok = [r for r in rs if abs(r["error_percent"]) <= lvl]
            if ok:
                r = min(ok, key=lambda r: r["core_s_per_time_unit"])
                lines.append(f"| {PROBLEMS[p]} | {lvl} % | D/dx {r['resolution']:g}, {mesh_label(r)},"
                             f" {step_label(r)} | {r['error_percent']:+.1f} |"
                             f" {r['core_s_per_time_unit'] / 3600:.2g} per {unit} |")
            else:
                best = min(rs, key=lambda r: abs(r["error_percent"]))
                lines.append(f"| {PROBLEMS[p]} | {lvl} % | not reached by the runs made (closest:"
                             f" {best['error_percent']:+.1f} % at D/dx {best['resolution']:g},"
                             f" {step_label(best)}) | | |")
    return "\n".join(lines) + "\n"


def orders_table(rows):
    lines = ["| case | series | observed order | errors |", "|---|---|---|---|"]
    for p in PROBLEMS:
        rs = measured(rows, p)
        res = sorted((r for r in rs if r["sweep"] == "resolution"), key=lambda r: r["resolution"])
        if len(res) >= 2:
            s = order([(1 / r["resolution"], r["error_percent"]) for r in res])
            lines.append(f"| {p} | resolution | {'' if s is None else f'{s:.2f}'} | "
                         + ", ".join(f"D/dx {r['resolution']:g}: {r['error_percent']:+.2f} %" for r in res)
                         + " |")
        steps = [r for r in rs if r["sweep"] == "time step"]
        if steps:
            N, mesh = steps[0]["resolution"], steps[0]["mesh"]
            ts = steps + [r for r in res if r["resolution"] == N and r["mesh"] == mesh]
            key = (lambda r: -r["cfl"]) if p == "cubeSuspension" else (lambda r: r["cfl"])
            ts = sorted(ts, key=key)
            s = None
            if len(ts) >= 3:
                finest = ts[0]
                h = (lambda r: 1 / r["cfl"]) if p == "cubeSuspension" else (lambda r: r["cfl"])
                s = order([(h(r), r["value"] - finest["value"]) for r in ts[1:]])
            lines.append(f"| {p} | time step (differences from the smallest) | {'' if s is None else f'{s:.2f}'} | "
                         + ", ".join(f"{step_label(r)}: {r['error_percent']:+.2f} %" for r in ts) + " |")
    return "\n".join(lines) + "\n"


def write_documents(targets, root):
    begin, end = "<!-- accuracyCost: targets -->", "<!-- accuracyCost: end -->"
    for path in glob.glob(os.path.join(root, "doc", "07-*.md")):
        text = open(path).read()
        if begin not in text or end not in text:
            sys.exit(f"{path}: no {begin} ... {end} block for the targets table")
        head, rest = text.split(begin, 1)
        _, tail = rest.split(end, 1)
        new = head + begin + "\n" + targets + end + tail
        if new != text:
            tmp = path + ".tmp"
            open(tmp, "w").write(new)
            os.replace(tmp, path)
            print("wrote the targets into", os.path.relpath(path, root))


def main(path, documents=False):
    here = os.path.dirname(path)
    rows = load(path)
    plot(rows, os.path.join(here, "accuracyCost.png"))
    table(rows, os.path.join(here, "table.md"))
    targets = targets_table(rows)
    with open(os.path.join(here, "targets.md"), "w") as f:
        f.write(targets + "\n" + orders_table(rows))
    print(open(os.path.join(here, "targets.md")).read())
    if documents:
        write_documents(targets, os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))

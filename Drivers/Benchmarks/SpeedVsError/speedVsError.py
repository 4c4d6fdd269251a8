"""What the speed-against-error studies share (Documentation/SpeedVsError.md): running a driver and
reading numbers from what it prints, the order of convergence of an error, the Pareto front, and
the plot of errors against cost with the front marked."""
import math
import re
import subprocess
import sys


def run_driver(tool, driver, flags, folder):
    """Runs the driver with flags in folder; returns what it printed, or stops naming the run."""
    out = subprocess.run([driver] + flags, capture_output=True, text=True, cwd=folder)
    if out.returncode != 0:
        sys.exit(f"{tool}: {driver} {' '.join(flags)} failed: {out.stderr.strip()}")
    return out.stdout


def number_after(tool, pattern, text):
    """The number the regular expression's group 1 finds in text, or stops saying what is missing."""
    found = re.search(pattern, text)
    if not found:
        sys.exit(f"{tool}: no match for '{pattern}' in:\n{text}")
    return float(found.group(1))


def order(costs, errors):
    """The order of convergence: minus the slope of the least-squares line through log error
    against log cost."""
    xs = [math.log(c) for c in costs]
    ys = [math.log(max(e, 1e-300)) for e in errors]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return -sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def pareto(points):
    """The points (cost, error) no other point beats in both."""
    front, best = [], float("inf")
    for cost, error in sorted(points):
        if error < best:
            front.append((cost, error))
            best = error
    return front


def plot(path, panels, cost_label):
    """panels: a list of (title, {label: [(cost, error), ...]}, groups), where groups lists the sets
    of labels among which a Pareto front is drawn (one case each, all its settings)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(panels), figsize=(5.5 * len(panels), 4.5), sharey=True, squeeze=False)
    for ax, (title, lines, groups) in zip(axes[0], panels):
        for k, (label, points) in enumerate(lines.items()):
            style = "o-" if k % 2 == 0 else "s--"
            ax.loglog([c for c, _ in points], [max(e, 1e-17) for _, e in points], style,
                      color=f"C{k // 2}", mfc="none", label=label)
        for k, group in enumerate(groups):
            front = pareto([(c, max(e, 1e-17)) for label in group for c, e in lines[label]])
            ax.plot(*zip(*front), "k:", lw=2, label="Pareto front of each case" if k == 0 else None)
        ax.set_xlabel(cost_label)
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
    axes[0][0].set_ylabel("relative error")
    axes[0][-1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)

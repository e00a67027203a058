"""Error against wall time, shared by the bench plot scripts and scripts/study: one panel per
case, one line per series through its resolutions, each point labelled with its resolution.

    panels = {"DFG 2D-1 C_D": {"point": [(wall_seconds, error, "D/h=5"), ...], ...}, ...}
    figure(panels, "out.png", ylabel="|relative error|")

Log-log where every value is positive; a panel with a zero or negative value keeps a linear
y axis (a log axis would drop those points).
"""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def span_a_decade(ax, which, values):
    """Widens a log axis to over one decade around its values: below that matplotlib labels
    the minor ticks, which run into each other."""
    low, high = min(values), max(values)
    if high / low < 15:
        middle = (low * high) ** 0.5
        getattr(ax, f"set_{which}lim")(middle / 4, middle * 4)


def draw(ax, series, title=None, ylabel=None, legend_title=None, by_wall=True):
    """One panel: series = {name: [(wall, value, label), ...]}, each joined in order of wall
    time, or in the order given (by_wall=False: the order of the resolutions)."""
    values = [p[1] for points in series.values() for p in points]
    for name, points in sorted(series.items()):
        points = sorted(points) if by_wall else points
        ax.plot([p[0] for p in points], [p[1] for p in points], "o-", label=name)
        for wall, value, label in points:
            ax.annotate(label, (wall, value), fontsize=7, xytext=(3, 3), textcoords="offset points")
    walls = [p[0] for points in series.values() for p in points]
    ax.set_xscale("log")
    if walls:
        span_a_decade(ax, "x", walls)
    if values and all(v > 0 for v in values):
        ax.set_yscale("log")
        span_a_decade(ax, "y", values)
    ax.set(xlabel="wall time [s]", ylabel=ylabel, title=title)
    ax.grid(True, which="both", alpha=0.3)
    if series:
        ax.legend(title=legend_title)


def axes(count, width=6, height=4.5):
    """A figure of `count` panels side by side and its axes."""
    fig, axs = plt.subplots(1, count, figsize=(width * count, height), squeeze=False)
    return fig, list(axs[0])


def save(fig, png_path):
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)
    plt.close(fig)


def figure(panels, png_path, ylabel, legend_title=None, by_wall=True):
    """One panel per entry of panels = {title: series}, the y label on the first."""
    fig, axs = axes(len(panels))
    for i, (ax, (title, series)) in enumerate(zip(axs, sorted(panels.items()))):
        draw(ax, series, title=title, ylabel=ylabel if i == 0 else None, legend_title=legend_title,
             by_wall=by_wall)
    save(fig, png_path)

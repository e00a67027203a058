"""Error against wall time, shared by the bench plot scripts and scripts/study: one panel per
case, one line per series through its resolutions, each point labelled with its resolution.

    panels = {"DFG 2D-1 C_D": {"point": [(wall_seconds, error, "D/h=5"), ...], ...}, ...}
    figure(panels, "out.png", ylabel="|relative error|")

A point may carry a fourth element, the range (low, high) its value takes over repeats
(e.g. body positions): drawn as a vertical bar in the line's colour through the point.

Log-log where every value is positive; a panel with a zero or negative value keeps a linear
y axis (a log axis would drop those points). On a log axis a bar whose low end is not
positive (a range through zero) runs to the bottom of the panel.
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
    time, or in the order given (by_wall=False: the order of the resolutions); a point's
    optional fourth element (low, high) is drawn as a bar."""
    values = [p[1] for points in series.values() for p in points]
    bars = []  # (wall, low, high, colour)
    for name, points in sorted(series.items(), key=lambda item: item[0]):
        points = sorted(points, key=lambda p: p[:2]) if by_wall else points
        line, = ax.plot([p[0] for p in points], [p[1] for p in points], "o-", label=name)
        for p in points:
            ax.annotate(p[2], (p[0], p[1]), fontsize=7, xytext=(3, 3), textcoords="offset points")
            if len(p) > 3 and p[3] is not None:
                bars.append((p[0], p[3][0], p[3][1], line.get_color()))
    walls = [p[0] for points in series.values() for p in points]
    ax.set_xscale("log")
    if walls:
        span_a_decade(ax, "x", walls)
    log = bool(values) and all(v > 0 for v in values)
    if log:
        ax.set_yscale("log")
        span_a_decade(ax, "y", values + [v for _, low, high, _ in bars for v in (low, high) if v > 0])
    if bars:
        if log:  # the bars within the axis the points and the bars' positive ends set
            ax.update_datalim([(wall, v) for wall, low, high, _ in bars for v in (low, high) if v > 0])
            ax.autoscale_view()
        bottom, top = ax.get_ylim()
        for wall, low, high, colour in bars:
            ax.vlines(wall, max(low, bottom) if log else low, high, colors=colour, lw=1.5, alpha=0.6)
        if log:  # a bar through zero ends at the bottom, which must not move down to it
            ax.set_ylim(bottom, top)
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

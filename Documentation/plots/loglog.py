"""One log-log figure, styled alike for every plot in Documentation/plots."""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def save_loglog(name, series, xlabel, ylabel, title, hline=None):
    """series: [(x, y, marker, label)]; hline: (y, label) or None.
    Writes Documentation/plots/<name>.png and returns its path."""
    plt.figure(figsize=(5.5, 4))
    for x, y, marker, label in series:
        plt.loglog(x, y, marker, label=label)
    if hline:
        plt.axhline(hline[0], color="gray", ls=":", label=hline[1])
    plt.xlabel(xlabel)
    plt.ylabel(ylabel)
    plt.title(title)
    plt.legend(fontsize=8)
    plt.grid(True, which="both", alpha=0.3)
    plt.tight_layout()
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), name + ".png")
    plt.savefig(out, dpi=120)
    plt.close()
    return out

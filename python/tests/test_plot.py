# gyrores.plot on matplotlib axes (skipped without matplotlib): each helper draws the figure's
# data, with the values the exact functions give, and labels every curve.
import math

import pytest

import gyrores

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import gyrores.plot as gp  # noqa: E402


@pytest.fixture
def ax():
    fig, ax = plt.subplots(figsize=(5, 3.5))
    yield ax
    plt.close(fig)


def _legend_texts(ax):
    legend = ax.get_legend()
    assert legend is not None
    texts = [t.get_text() for t in legend.get_texts()]
    assert texts and all(texts)
    return texts


def test_phase_marks_the_exact_inscribed_radius(ax):
    assert gp.phase(ax, 6, 5) is ax
    r = gyrores.pair(6, 5, digits=15).r_res
    assert any(f"inscribed r = {r:.4g}" in t for t in _legend_texts(ax))
    d = gp.phase_data(6, 5)
    assert d["trajectory"].shape[1] == 2 and abs(d["r_inscribed"] - r) < 1e-12
    assert math.hypot(*d["first_min"]) == pytest.approx(r, rel=1e-9)


def test_energy_on_a_log_axis_shows_the_minimum(ax):
    gp.energy(ax, 6, 5)
    assert ax.get_yscale() == "log"  # min H_q = 1.3e-3 is < 1% of the range: auto log view
    h_min = gyrores.pair(6, 5, digits=15).h_min
    lo, hi = ax.get_ylim()
    assert lo < h_min < hi
    assert any(f"{h_min:.4g}" in t for t in _legend_texts(ax))
    fig, ax2 = plt.subplots()
    gp.energy(ax2, n=0.3, log=False)
    assert ax2.get_yscale() == "linear"
    plt.close(fig)


def test_pareto_keeps_zero_pairs_off_the_log_axis(ax):
    gp.pareto(ax, 40)
    rows, _ = gyrores.sweep(40)
    zeros = int((rows["r_res"] == 0).sum())
    assert any(f"r_res = 0 ({zeros} pairs, below)" in t for t in _legend_texts(ax))
    # No point of the log axis carries r_res = 0 (or a stand-in floor for it).
    for line in ax.get_lines():
        assert (line.get_ydata() > 0).all()


def test_coupling_floor(ax):
    gp.coupling_floor(ax, n2="1/13", convergents=5)
    assert ax.get_xscale() == "log" and _legend_texts(ax)


def test_bad_target_is_a_usage_error(ax):
    with pytest.raises(gyrores.UsageError, match="plot.phase"):
        gp.phase(ax, 6, 5, n=0.3)

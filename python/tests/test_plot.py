# gyrores.plot on matplotlib axes (skipped without matplotlib): each helper draws the figure's
# data, with the values the exact functions give, and labels every curve; the figures are fit for
# a paper as they are: three labelled ticks on every axis, keys off the data, curves that reach
# their marks, a zoom on the inscribed circle, the r_res = 0 strip clear of the tick labels, the
# Pareto scatter thinned and rasterised as the CLI's.
import math

import numpy as np
import pytest

import gyrores

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PathCollection  # noqa: E402

import gyrores.plot as gp  # noqa: E402


@pytest.fixture
def ax():
    fig, ax = plt.subplots(figsize=(5, 3.5))
    yield ax
    plt.close(fig)


@pytest.fixture(autouse=True)
def close_all():
    yield
    plt.close("all")


def _legend_texts(ax):
    legend = ax.get_legend()
    assert legend is not None
    texts = [t.get_text() for t in legend.get_texts()]
    assert texts and all(texts)
    return texts


def _labelled(labels, lo, hi, coord):
    """The tick labels shown inside [lo, hi] (coord 0: an x axis, 1: a y axis)."""
    lo, hi = min(lo, hi), max(lo, hi)
    slack = 1e-9 * (hi - lo)
    return [t for t in labels if t.get_text() and lo - slack <= t.get_position()[coord] <= hi + slack]


def _check_ticks(a):
    a.figure.canvas.draw()  # formats the labels
    assert len(_labelled(a.get_xticklabels(), *a.get_xlim(), 0)) >= 3, a.get_title()
    assert len(_labelled(a.get_yticklabels(), *a.get_ylim(), 1)) >= 3, a.get_title()


def _display_points(a):
    """Every data point of a's lines and scatters, in display coordinates (inside a's box)."""
    pts = []
    for line in a.get_lines():
        xy = np.column_stack([np.asarray(line.get_xdata(), float), np.asarray(line.get_ydata(), float)])
        xy = xy[np.isfinite(xy).all(axis=1)]
        if len(xy):
            pts.append(line.get_transform().transform(xy))
    for c in a.collections:
        if isinstance(c, PathCollection) and len(c.get_offsets()):
            pts.append(c.get_offset_transform().transform(np.asarray(c.get_offsets(), float)))
    if not pts:
        return np.empty((0, 2))
    p = np.concatenate(pts)
    box = a.bbox
    return p[(p[:, 0] >= box.x0) & (p[:, 0] <= box.x1) & (p[:, 1] >= box.y0) & (p[:, 1] <= box.y1)]


def _key_off_the_data(a):
    """The key's box holds no point of any curve or mark of a (or of the zoom beside it)."""
    a.figure.canvas.draw()
    legend = a.get_legend()
    assert legend is not None
    box = legend.get_window_extent()
    for other in a.figure.axes:
        p = _display_points(other)
        inside = (p[:, 0] >= box.x0) & (p[:, 0] <= box.x1) & (p[:, 1] >= box.y0) & (p[:, 1] <= box.y1)
        assert not inside.any(), f"key of '{a.get_title()}' over {int(inside.sum())} points of '{other.get_title()}'"


def test_phase_marks_the_exact_inscribed_radius(ax):
    assert gp.phase(ax, 6, 5) is ax
    r = gyrores.pair(6, 5, digits=15).r_res
    assert any(f"{r:.4g}" in t and "inscribed" in t for t in _legend_texts(ax))
    d = gp.phase_data(6, 5)
    assert d["trajectory"].shape[1] == 2 and abs(d["r_inscribed"] - r) < 1e-12
    assert math.hypot(*d["first_min"]) == pytest.approx(r, rel=1e-9)


def test_phase_without_axes_makes_a_figure_with_a_zoom_on_the_inscribed_circle():
    ax = gp.phase(tau=6, sigma=5)
    assert gp.phase(6, 5).figure is not ax.figure  # plot.phase(6, 5): a figure of its own too
    zoom = ax.gyrores_zoom
    assert zoom is not None and zoom in ax.figure.axes
    r = gyrores.pair(6, 5, digits=15).r_res
    lo, hi = zoom.get_xlim()
    assert lo < -r and r < hi < 10 * r  # the zoom frames the inscribed circle
    radii = [np.hypot(line.get_xdata(), line.get_ydata()) for line in zoom.get_lines() if len(line.get_xdata()) > 100]
    assert any(np.allclose(rr, r, rtol=1e-9) for rr in radii)  # the inscribed circle is drawn there
    # The maximal circle is drawn over the envelope (higher zorder), dashed.
    lines = {line.get_label(): line for line in ax.get_lines()}
    env = next(v for k, v in lines.items() if k.startswith("envelope"))
    big = next(v for k, v in lines.items() if k.startswith("maximal"))
    assert big.get_zorder() > env.get_zorder() and big.get_linestyle() != "-"


def test_labels_are_mathtext(ax):
    gp.energy(ax, 6, 5)
    assert "$" in ax.get_xlabel() and any("$H_q$" in t for t in _legend_texts(ax))
    fig, a2 = plt.subplots()
    gp.phase(a2, 6, 5)
    assert "$" in a2.get_ylabel()


def test_every_axis_has_three_labelled_ticks():
    for a in (gp.phase(None, 6, 5), gp.energy(None, 6, 5), gp.energy(None, n=2, t_end=50), gp.pareto(None, 60)):
        _check_ticks(a)
    _check_ticks(gp.phase(None, 6, 5).gyrores_zoom)


def test_keys_hold_no_data_point():
    for a in (gp.phase(None, 6, 5), gp.energy(None, 6, 5), gp.energy(None, n=2, t_end=50), gp.pareto(None, 80)):
        _key_off_the_data(a)
    fig, a = plt.subplots(figsize=(5, 3.5))
    _key_off_the_data(gp.phase(a, 6, 5))  # on axes of one's own, without a zoom
    _key_off_the_data(gp.phase(None, 6, 5).gyrores_zoom)


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


def test_the_curve_reaches_each_marked_minimum():
    # n = 2 over [0, 50]: the minimum 1.4e-7 at t = 26.68 lies in a dip far narrower than the
    # uniform spacing; the curve is refined around it (and (6, 5) at both of its minimisers).
    for kw in ({"n": 2, "t_end": 50}, {"tau": 6, "sigma": 5}):
        a = gp.energy(None, log=True, **kw)
        curve = next(line for line in a.get_lines() if line.get_label() == "$H_q$")
        t, h = np.asarray(curve.get_xdata()), np.asarray(curve.get_ydata())
        marks = [line for line in a.get_lines() if line.get_marker() == "o"]
        assert marks
        for m in marks:
            for tm, hm in zip(m.get_xdata(), m.get_ydata()):
                near = h[np.abs(t - tm) <= 1e-6 * max(1.0, tm)]
                assert len(near) and near.min() == pytest.approx(hm, rel=1e-6), (kw, tm, hm)


def test_pareto_keeps_zero_pairs_off_the_log_axis_and_the_tick_labels(ax):
    gp.pareto(ax, 40)
    rows, _ = gyrores.sweep(40)
    zeros = int((rows["r_res"] == 0).sum())
    assert any(f"({zeros} pairs" in t for t in _legend_texts(ax))
    # No point of the log axis carries r_res = 0 (or a stand-in floor for it).
    for line in ax.get_lines():
        assert (np.asarray(line.get_ydata()) > 0).all()
    # The zeros sit on a strip above the axes, clear of the x tick labels below them.
    strip = ax.gyrores_strip
    ax.figure.canvas.draw()
    ticks_top = max(t.get_window_extent().y1 for t in ax.get_xticklabels() if t.get_text())
    pts = np.concatenate([c.get_offset_transform().transform(c.get_offsets()) for c in strip.collections])
    assert len(pts) >= zeros
    assert (pts[:, 1] > ax.bbox.y1).all() and (pts[:, 1] > ticks_top).all()


def test_pareto_thins_and_rasterises_as_the_cli():
    # Order 600: 54 749 pairs, above the CLI's 50 000: one point per 2 x 2 pixels of the figure.
    fig, a = plt.subplots(figsize=(3, 2), dpi=100)
    gp.pareto(a, 600)
    scatter = [c for c in a.collections if isinstance(c, PathCollection) and len(c.get_offsets())]
    assert scatter
    shown = sum(len(c.get_offsets()) for c in scatter)
    assert shown <= (300 // 2) * (200 // 2) + 50  # every cell of a 300 x 200 pixel figure at most once
    assert all(c.get_rasterized() for c in scatter)
    assert any("thinned from" in t for t in _legend_texts(a))
    d = gp.pareto_data(600, width=300, height=200)
    assert d["thinned"] and d["pairs"] > 50000


def test_coupling_floor(ax):
    gp.coupling_floor(ax, n2="1/13", convergents=5)
    assert ax.get_xscale() == "log" and _legend_texts(ax)


def test_bad_target_is_a_usage_error(ax):
    with pytest.raises(gyrores.UsageError, match="plot.phase"):
        gp.phase(ax, 6, 5, n=0.3)

"""Plot helpers on matplotlib axes: the CLI's figures (``gyrores plot ...``) from the same data.

Each function draws on the ``ax`` it is given and returns it; without one (``ax=None``, the
default) it makes a figure of its own, ready for a paper (constrained layout, 3.5 inches wide
for one panel). ``plot.phase(6, 5)`` and ``plot.phase(ax, 6, 5)`` both work. matplotlib is
needed only by the caller (Debian: python3-matplotlib): this module imports it only to make a
figure. The data: design/figures.hpp (phase portraits, H_q and H_z, in double for plotting, the
marked values from the exact solvers; the curves refined around every marked minimum, so that
they reach their marks), app/figures.hpp (the Pareto figure's points, thinned as the CLI thins
them) and gyrores.coupling (the convergents of any n).

As in the CLI's figures, every key sits outside the axes (right of them), off the data, and
labels are matplotlib mathtext ($H_q$, $r_{\\rm res}$). When you save a figure of your own
axes, pass ``bbox_inches="tight"`` so that the keys are kept.

- phase(ax, tau, sigma) or phase(ax, n=...): the trajectory in (q, q'), the envelope, the
  maximal circle qdot0 (dashed, over the envelope) and, on a zoom panel, the inscribed circle
  r_res and the first minimiser (paper Fig. 1/3).
- energy(ax, tau, sigma) or energy(ax, n=...): H_q(t) and H_z(t) with min H_q marked at each of
  its times and t_first; log=True (or "auto": when min H_q < 1% of the range) puts H_q on a log
  axis, where its minimum is visible (paper Fig. 2).
- pareto(ax, max_order): r_res against the first-hit time of every pair (grey, rasterised, thinned
  above 50,000 pairs to one per 2 x 2 pixels as the CLI does), the Pareto front (line); the pairs
  with r_res = 0 (delta = 2 mod 4) drawn on a strip of their own above the log axis, never on a
  fake floor of it (paper Fig. 4).
- coupling_floor(ax, n): min H_q = r_res^2/2 of the resonant convergents of W1/W2 against
  their first-hit times, on log axes: how low the energy of q dips, and when, as the
  convergents approach an irrational n.
"""

import math

from . import _args, _gyrores
from . import coupling as _coupling

# A figure made here: one panel 3.5 inches wide (a journal column), two side by side 7.
_ONE_PANEL = (3.5, 2.6)
_TWO_PANELS = (7.0, 3.6)


def _is_axes(ax):
    return ax is not None and hasattr(ax, "plot") and hasattr(ax, "figure")


def _shift(ax, args):
    """(ax, args): plot.phase(6, 5) is plot.phase(None, 6, 5) (each argument moves up one place)."""
    if ax is None or _is_axes(ax):
        return ax, list(args)
    if args[-1] is not None:
        raise _gyrores.UsageError("gyrores.plot: the first argument is the matplotlib Axes (or None), got "
                                  f"{type(ax).__name__} with every place after it taken")
    return None, [ax] + list(args[:-1])


def _new_axes(ncols=1, size=None):
    import matplotlib.pyplot as plt

    if ncols == 2:  # the phase figure: its keys below the panels, room made for them
        fig, axes = plt.subplots(1, 2, figsize=size or _TWO_PANELS)
        fig.subplots_adjust(left=0.09, right=0.98, top=0.9, bottom=0.36, wspace=0.35)
        return axes
    fig, axes = plt.subplots(1, ncols, figsize=size or _ONE_PANEL, layout="constrained")
    return axes


def _key(ax, **kw):
    """The key outside the axes, at their right: off every curve and mark."""
    kw.setdefault("fontsize", "small")
    return ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0, **kw)


def _enough_log_ticks(ax):
    """At least three labelled ticks on each log axis of ax: matplotlib labels only the powers of
    ten, so an axis spanning less than three decades gets 1, 3 (or 1, 2, 5) x 10^k too."""
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    for axis, lim in ((ax.xaxis, ax.get_xlim()), (ax.yaxis, ax.get_ylim())):
        lo, hi = sorted(lim)
        if axis.get_scale() != "log" or not lo > 0:
            continue
        decades = math.floor(math.log10(hi)) - math.ceil(math.log10(lo)) + 1
        if decades >= 3:
            continue
        axis.set_major_locator(LogLocator(base=10, subs=(1.0, 3.0) if decades == 2 else (1.0, 2.0, 5.0)))
        axis.set_major_formatter(FuncFormatter(_power_label))
        axis.set_minor_formatter(NullFormatter())


def _power_label(v, _pos=None):
    """m x 10^k in mathtext ("$3\\times10^{-2}$", "$10^{-3}$"); plain from 1 to 900."""
    if not v > 0:
        return ""
    k = math.floor(math.log10(v) + 1e-9)
    m = round(v / 10 ** k)
    if 0 <= k <= 2:
        return f"${m * 10 ** k:g}$"
    return f"$10^{{{k}}}$" if m == 1 else f"${m}\\times10^{{{k}}}$"


def _target(tau, sigma, n, function):
    """(tau, sigma, None) for a pair, (None, None, n as float) for a coupling."""
    if n is None:
        if tau is None or sigma is None:
            raise _gyrores.UsageError(f"plot.{function}(): give a pair (tau, sigma) or a coupling n=")
        return _args.integer(tau, f"plot.{function}", "tau"), _args.integer(sigma, f"plot.{function}", "sigma"), None
    if tau is not None or sigma is not None:
        raise _gyrores.UsageError(f"plot.{function}(): give a pair (tau, sigma) or a coupling n=, not both")
    return None, None, float(n)


def phase_data(tau=None, sigma=None, n=None, qdot0=1.0, t_span=0.0):
    """The data of phase(): a dict of NumPy arrays (trajectory, envelope: (N, 2)) and numbers.

    A coupling n is drawn over [0, t_span] (0: 200 pi/n, as the CLI and the paper's Fig. 1a)."""
    t, s, nv = _target(tau, sigma, n, "phase")
    return _gyrores._phase_data(t, s, nv, float(qdot0), float(t_span))


def energy_data(tau=None, sigma=None, n=None, qdot0=1.0, t_end=0.0):
    """The data of energy(): t, h_q, h_z (NumPy arrays), t_first, h_min, t_minima (every time
    of the span where H_q is h_min), t_proxy, t_end."""
    t, s, nv = _target(tau, sigma, n, "energy")
    if nv is not None and not t_end:
        t_end = 200 * math.pi / nv  # the span of phase(); the CLI's `plot energy` draws 8 pi/n
    return _gyrores._energy_data(t, s, nv, float(qdot0), float(t_end))


def _circle(r, k=720):
    angles = [2 * math.pi * i / k for i in range(k + 1)]
    return [r * math.cos(a) for a in angles], [r * math.sin(a) for a in angles]


def phase(ax=None, tau=None, sigma=None, n=None, qdot0=1.0, t_span=0.0, zoom=None):
    """The phase portrait (q, q') of the pair (tau, sigma), or of coupling n over [0, t_span].

    zoom: an Axes for the zoom on the inscribed circle, True (an inset right of ax), False, or
    None: a zoom panel when the figure is made here (ax=None), none on axes of your own. The zoom
    axes is returned as ``ax.gyrores_zoom`` (None without one)."""
    ax, rest = _shift(ax, (tau, sigma))
    tau, sigma = rest
    d = phase_data(tau, sigma, n, qdot0, t_span)
    if ax is None:
        ax, made_zoom = _new_axes(2)
        zoom = made_zoom if zoom is None or zoom is True else zoom
        if zoom is False:
            made_zoom.remove()
    elif zoom is True:
        zoom = ax.inset_axes([1.08, 0.0, 0.9, 0.9])
    if not _is_axes(zoom):
        zoom = None
    tr, env = d["trajectory"], d["envelope"]
    r, R = d["r_inscribed"], d["r_max"]
    ax.plot(tr[:, 0], tr[:, 1], lw=0.5, color="C0", label="trajectory")
    ax.plot(env[:, 0], env[:, 1], lw=2.0, color="C3", label=r"envelope $x_d(\varphi)$", zorder=3)
    # Drawn over the envelope, dashed: where the two run together both stay visible.
    ax.plot(*_circle(R), lw=1.0, ls=(0, (5, 4)), color="k", label=rf"maximal circle $r = \dot q(0) = {R:.4g}$",
            zorder=4)
    ax.set_aspect("equal")
    ax.set_xlabel(r"$q$")
    ax.set_ylabel(r"$\dot q$")
    what = f"pair ({d['tau']}, {d['sigma']})" if d["resonant"] else f"$n = {d['n']:.6g}$"
    ax.set_title(f"Phase portrait, {what}", fontsize="medium")
    inscribed = (r"inscribed $r_{\rm res}$" if d["inscribed_is_infimum"] else "min radius on the span") + f" $= {r:.4g}$"
    first = rf"first minimum, $t = {d['t_first']:.5g}$"
    if zoom is None:
        ax.plot(*_circle(r), lw=1.0, ls="--", color="k", label=inscribed)
        ax.plot(*d["first_min"], "o", color="C2", ms=4, label=first, zorder=5)
        _key(ax)
    else:
        w = 3 * (r if r > 0 else 0.02 * d["qdot0"])
        ax.add_patch(_zoom_box(w))
        zoom.plot(tr[:, 0], tr[:, 1], lw=0.5, color="C0")
        for seg in d["near_minimisers"]:
            zoom.plot(seg[:, 0], seg[:, 1], lw=1.0, color="C0")
        if r > 0:
            zoom.plot(*_circle(r), lw=1.0, ls="--", color="k", label=inscribed)
        else:
            zoom.plot([0], [0], "o", mfc="none", color="k", ms=8, label=r"$r_{\rm res} = 0$ (degenerate)")
        zoom.plot(*d["first_min"], "o", color="C2", ms=5, label=first, zorder=5)
        zoom.set_xlim(-w, w)
        zoom.set_ylim(-w, w)
        zoom.set_aspect("equal")
        zoom.set_xlabel(r"$q$")
        zoom.set_title(rf"zoom: $|q|, |\dot q| \leq {w:.3g}$", fontsize="medium")
        # Both keys below their panels, off the data.
        for a in (ax, zoom):
            a.legend(loc="upper center", bbox_to_anchor=(0.5, -0.22), borderaxespad=0.0, fontsize="small")
    ax.gyrores_zoom = zoom
    return ax


def _zoom_box(w):
    from matplotlib.patches import Rectangle

    return Rectangle((-w, -w), 2 * w, 2 * w, fill=False, ls=":", lw=0.8, color="0.3")


def energy(ax=None, tau=None, sigma=None, n=None, qdot0=1.0, t_end=0.0, log="auto"):
    """H_q(t) and H_z(t) with min H_q marked at each of its times; log: True, False or "auto"."""
    ax, rest = _shift(ax, (tau, sigma))
    tau, sigma = rest
    d = energy_data(tau, sigma, n, qdot0, t_end)
    if ax is None:
        ax = _new_axes(1, (5.0, 2.6))
    t, hq, hz = d["t"], d["h_q"], d["h_z"]
    span = max(hq.max(), hz.max()) - min(hq.min(), hz.min())
    use_log = (d["h_min"] > 0 and d["h_min"] < 0.01 * span) if log == "auto" else bool(log)
    ax.plot(t, hq, lw=0.8, color="C0", label=r"$H_q$")
    if not use_log:
        ax.plot(t, hz, lw=0.8, color="C1", label=r"$H_z$")
    ax.axvline(d["t_first"], color="C2", lw=0.8, ls="--", label=rf"$t_{{\rm first}} = {d['t_first']:.5g}$")
    ax.axvline(d["t_proxy"], color="0.5", lw=0.8, ls=":", label=rf"proxy $\pi/n = {d['t_proxy']:.5g}$")
    ax.plot([d["t_first"]], [d["h_min"]], "o", color="C2", ms=4, label=rf"min $H_q = {d['h_min']:.4g}$", zorder=5)
    others = [x for x in d["t_minima"] if x != d["t_first"]]
    if others:
        ax.plot(others, [d["h_min"]] * len(others), "o", mfc="none", color="C2", ms=4,
                label="the same minimum, again", zorder=5)
    if use_log:
        ax.set_yscale("log")
        ax.set_ylim(d["h_min"] / 10 if d["h_min"] > 0 else None, hq.max() * 2)
    ax.set_xlim(0, d["t_end"])
    ax.set_xlabel(r"$t$")
    ax.set_ylabel("energy" + (r" ($H_q$, log)" if use_log else ""))
    ax.set_title("Energy exchange", fontsize="medium")
    _enough_log_ticks(ax)
    _key(ax)
    return ax


def pareto_data(max_order, orientation="absorb", proxy=False, exclude_degenerate=False, width=900, height=640):
    """The points pareto() draws, as the CLI's `plot pareto` draws them: a dict with `pairs` (how
    many), `thinned` (more than `thin_above` = 50,000 pairs: the scattered ones thinned to one per
    2 x 2 pixels of a width x height figure), and columns t, r_res, tau, sigma for `positive`,
    `zeros` (r_res = 0), `front`, `front_zeros` and `labelled` (front pairs worth naming)."""
    return _gyrores._pareto_figure_data(_args.integer(max_order, "plot.pareto", "max_order"), str(orientation),
                                        bool(proxy), bool(exclude_degenerate), int(width), int(height))


def pareto(ax=None, max_order=None, orientation="absorb", proxy=False, exclude_degenerate=False):
    """r_res against the first-hit time of every pair up to max_order, and the Pareto front.

    The r_res = 0 pairs (delta = 2 mod 4) sit on a strip of their own above the log axis
    (``ax.gyrores_strip``), clear of the tick labels. Above 50,000 pairs the grey scatter is
    thinned as the CLI thins it (one point per 2 x 2 pixels of the figure), and it is rasterised.
    """
    ax, rest = _shift(ax, (max_order,))
    (max_order,) = rest
    if max_order is None:
        raise _gyrores.UsageError("plot.pareto(): give max_order")
    if ax is None:
        ax = _new_axes(1, (5.0, 3.4))
    w, h = (ax.figure.get_size_inches() * ax.figure.dpi).tolist()
    d = pareto_data(max_order, orientation, proxy, exclude_degenerate, max(100, int(w)), max(100, int(h)))
    pos, front = d["positive"], d["front"]
    thinned = f", thinned from {d['pairs']}" if d["thinned"] else ""
    ax.scatter(pos["t"], pos["r_res"], s=2, color="0.6", linewidths=0, rasterized=len(pos["t"]) > 5000,
               label=rf"pairs, $\tau + \sigma \leq {max_order}${thinned}")
    ax.plot(front["t"], front["r_res"], "-o", ms=3, lw=1.0, color="C3", label=f"Pareto front ({orientation})")
    ax.set_yscale("log")
    ax.set_xscale("log")
    ax.set_xlabel(r"first-hit time " + (r"(proxy $\pi/n$)" if proxy else r"$t_{\rm first}$"))
    ax.set_ylabel(r"$r_{\rm res}$")
    zeros, fz = d["zeros"], d["front_zeros"]
    strip = None
    if len(zeros["t"]) or len(fz["t"]):
        # The exact zeros on a strip of their own just above the axes (sharing the time axis): a
        # log axis has no 0, and below the axes the tick labels are.
        strip = ax.inset_axes([0.0, 1.03, 1.0, 0.12], sharex=ax)
        strip.scatter(zeros["t"], [0] * len(zeros["t"]), s=4, marker="x", linewidths=0.6, color="C5",
                      rasterized=len(zeros["t"]) > 5000)
        if len(fz["t"]):
            strip.plot(fz["t"], [0] * len(fz["t"]), "o", ms=4, color="C3")
        strip.set_ylim(-1, 1)
        strip.set_yticks([])
        strip.tick_params(labelbottom=False)
        strip.set_ylabel(r"$r_{\rm res}=0$", rotation=0, ha="right", va="center", fontsize="small")
        ax.scatter([], [], s=4, marker="x", color="C5", label=rf"$r_{{\rm res}} = 0$ ({len(zeros['t'])} pairs, strip above)")
        strip.set_title(rf"$r_{{\rm res}}$ against time, $\tau + \sigma \leq {max_order}$", fontsize="medium")
    else:
        ax.set_title(rf"$r_{{\rm res}}$ against time, $\tau + \sigma \leq {max_order}$", fontsize="medium")
    ax.gyrores_strip = strip
    _enough_log_ticks(ax)
    _key(ax, markerscale=2)
    return ax


def coupling_floor(ax=None, n=None, n2=None, convergents=12):
    """min H_q of the resonant convergents (tau, sigma) of coupling n against t_first (log axes)."""
    ax, rest = _shift(ax, (n,))
    (n,) = rest
    c = _coupling(n=n, n2=n2, convergents=convergents, digits=17)
    if ax is None:
        ax = _new_axes(1, (5.0, 3.0))
    pts = [(float(k["t_first"]), float(k["r_res"]) ** 2 / 2, k["tau"], k["sigma"])
           for k in c["convergents"] if "r_res" in k and float(k["r_res"]) > 0]
    if pts:
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "-o", ms=3, color="C0",
                label=r"convergents: min $H_q = r_{\rm res}^2/2$")
        for t, h, tau, sigma in pts:
            ax.annotate(f"({tau},{sigma})", (t, h), fontsize="x-small", xytext=(3, 3), textcoords="offset points")
    if c.get("h_min_horizon") and float(c["h_min_horizon"]) > 0:
        ax.axhline(float(c["h_min_horizon"]), color="C2", ls="--", lw=0.8,
                   label=rf"min $H_q$ over $[0, {c['horizon']}]$")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(r"first-hit time $t_{\rm first}$")
    ax.set_ylabel(r"min $H_q$")
    ax.set_title(f"Energy floor of the convergents, $n = {float(c['n']):.6g}$", fontsize="medium")
    _enough_log_ticks(ax)
    _key(ax)
    return ax

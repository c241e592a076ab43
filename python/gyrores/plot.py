"""Plot helpers on matplotlib axes: the CLI's figures (``gyrores plot ...``) from the same data.

Each function draws on the ``ax`` it is given (``fig, ax = plt.subplots()``) and returns ``ax``;
matplotlib is needed only by the caller (Debian: python3-matplotlib), this module never imports
it. The data: design/figures.hpp (phase portraits, H_q and H_z, in double for plotting, the
marked values from the exact solvers), gyrores.sweep / gyrores.pareto (the Pareto figure) and
gyrores.coupling (the convergents of any n).

- phase(ax, tau, sigma) or phase(ax, n=...): the trajectory in (q, q'), the envelope, the
  inscribed circle r_res and the maximal circle qdot0, the first minimiser (paper Fig. 1/3).
- energy(ax, tau, sigma) or energy(ax, n=...): H_q(t) and H_z(t) with min H_q and t_first
  marked; log=True (or "auto": when min H_q < 1% of the range) puts H_q on a log axis, where
  its minimum is visible (paper Fig. 2).
- pareto(ax, max_order): r_res against the first-hit time of every pair (grey), the Pareto front
  (line); the pairs with r_res = 0 (delta = 2 mod 4) drawn on their own strip below the log
  axis, never on a fake floor of it (paper Fig. 4).
- coupling_floor(ax, n): min H_q = r_res^2/2 of the resonant convergents of W1/W2 against
  their first-hit times, on log axes: how low the energy of q dips, and when, as the
  convergents approach an irrational n.
"""

import math

from . import _args, _gyrores
from . import coupling as _coupling
from . import pareto as _pareto
from . import sweep as _sweep


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
    """The data of energy(): t, h_q, h_z (NumPy arrays), t_first, h_min, t_proxy, t_end."""
    t, s, nv = _target(tau, sigma, n, "energy")
    if nv is not None and not t_end:
        t_end = 200 * math.pi / nv  # the span of phase(); the CLI's `plot energy` draws 8 pi/n
    return _gyrores._energy_data(t, s, nv, float(qdot0), float(t_end))


def phase(ax, tau=None, sigma=None, n=None, qdot0=1.0, t_span=0.0):
    """The phase portrait (q, q') of the pair (tau, sigma), or of coupling n over [0, t_span]."""
    d = phase_data(tau, sigma, n, qdot0, t_span)
    tr, env = d["trajectory"], d["envelope"]
    ax.plot(tr[:, 0], tr[:, 1], lw=0.5, color="C0", label="trajectory")
    ax.plot(env[:, 0], env[:, 1], lw=1.2, color="C3", label="envelope")
    circle = [(math.cos(a), math.sin(a)) for a in (2 * math.pi * k / 400 for k in range(401))]
    r = d["r_inscribed"]
    ax.plot([r * c for c, _ in circle], [r * s for _, s in circle], lw=1.2, color="C2",
            label=f"inscribed r = {r:.4g}" + ("" if d["inscribed_is_infimum"] else " (over the span)"))
    R = d["r_max"]
    ax.plot([R * c for c, _ in circle], [R * s for _, s in circle], lw=0.8, ls="--", color="0.4",
            label=f"maximal r = {R:.4g}")
    ax.plot(*d["first_min"], "o", color="C2", ms=4, label=f"first minimum, t = {d['t_first']:.4g}")
    ax.set_aspect("equal")
    ax.set_xlabel("q")
    ax.set_ylabel("q'")
    what = f"pair ({d['tau']}, {d['sigma']})" if d["resonant"] else f"n = {d['n']:.6g}"
    ax.set_title(f"Phase portrait, {what}")
    ax.legend(loc="upper right", fontsize="small")
    return ax


def energy(ax, tau=None, sigma=None, n=None, qdot0=1.0, t_end=0.0, log="auto"):
    """H_q(t) and H_z(t) with min H_q and its first time marked; log: True, False or "auto"."""
    d = energy_data(tau, sigma, n, qdot0, t_end)
    t, hq, hz = d["t"], d["h_q"], d["h_z"]
    span = max(hq.max(), hz.max()) - min(hq.min(), hz.min())
    use_log = (d["h_min"] > 0 and d["h_min"] < 0.01 * span) if log == "auto" else bool(log)
    ax.plot(t, hq, lw=0.8, color="C0", label="H_q")
    if not use_log:
        ax.plot(t, hz, lw=0.8, color="C1", label="H_z")
    ax.axvline(d["t_first"], color="C2", lw=0.8, ls="--", label=f"t_first = {d['t_first']:.4g}")
    ax.axvline(d["t_proxy"], color="0.5", lw=0.8, ls=":", label=f"proxy pi/n = {d['t_proxy']:.4g}")
    ax.plot([d["t_first"]], [d["h_min"]], "o", color="C2", ms=4, label=f"min H_q = {d['h_min']:.4g}")
    if use_log:
        ax.set_yscale("log")
        ax.set_ylim(d["h_min"] / 10 if d["h_min"] > 0 else None, hq.max() * 2)
    ax.set_xlabel("t")
    ax.set_ylabel("energy" + (" (log, H_q only)" if use_log else ""))
    ax.set_title("Energy exchange" + (" near min H_q" if use_log else ""))
    ax.legend(loc="best", fontsize="small")
    return ax


def pareto(ax, max_order, orientation="absorb", proxy=False):
    """r_res against the first-hit time of every pair up to max_order, and the Pareto front.

    The r_res = 0 pairs (delta = 2 mod 4) sit on a strip below the log axis, labelled as such.
    """
    rows, _ = _sweep(max_order)
    front = _pareto(max_order, orientation=orientation, proxy=proxy, digits=17)
    time_key = "t_min_paper" if proxy else "t_first"
    zero = rows["r_res"] == 0
    pos = ~zero & (rows["r_res"] > 0)
    ax.scatter(rows[time_key][pos], rows["r_res"][pos], s=2, color="0.7", label=f"pairs, order <= {max_order}",
               rasterized=len(rows) > 20000)
    on_axis = [p for p in front["front"] if p["r_res"] > 0]  # a front's r_res = 0 end goes on the strip
    fx = [float(p[time_key]) for p in on_axis]
    fy = [float(p["r_res"]) for p in on_axis]
    ax.plot(fx, fy, "-o", ms=3, color="C3", label=f"Pareto front ({orientation})")
    ax.set_yscale("log")
    ax.set_xscale("log")
    ax.set_xlabel("first-hit time" + (" (proxy pi/n)" if proxy else " t_first"))
    ax.set_ylabel("r_res")
    if zero.any():
        # The exact zeros on their own strip under the axis, in axes coordinates for y.
        ax.scatter(rows[time_key][zero], [-0.06] * int(zero.sum()), s=2, color="C0", clip_on=False,
                   transform=ax.get_xaxis_transform(), label=f"r_res = 0 ({int(zero.sum())} pairs, below)")
    ax.set_title(f"r_res against time, order <= {max_order}")
    ax.legend(loc="best", fontsize="small")
    return ax


def coupling_floor(ax, n=None, n2=None, convergents=12):
    """min H_q of the resonant convergents (tau, sigma) of coupling n against t_first (log axes)."""
    c = _coupling(n=n, n2=n2, convergents=convergents, digits=17)
    pts = [(float(k["t_first"]), float(k["r_res"]) ** 2 / 2, k["tau"], k["sigma"])
           for k in c["convergents"] if "r_res" in k and float(k["r_res"]) > 0]
    if pts:
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "-o", ms=3, color="C0",
                label="convergents: min H_q = r_res^2/2")
        for t, h, tau, sigma in pts:
            ax.annotate(f"({tau},{sigma})", (t, h), fontsize="x-small", xytext=(3, 3), textcoords="offset points")
    if c.get("h_min_horizon") and float(c["h_min_horizon"]) > 0:
        ax.axhline(float(c["h_min_horizon"]), color="C2", ls="--", lw=0.8,
                   label=f"min H_q over [0, {c['horizon']}]")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("first-hit time t_first")
    ax.set_ylabel("min H_q")
    ax.set_title(f"Energy floor of the convergents, n = {float(c['n']):.6g}")
    ax.legend(loc="best", fontsize="small")
    return ax

# qdot0, pair and physical units in gyrores.coupling and gyrores.plant (docs/units.md), against
# the CLI's JSON (the same library call) and against the dimensionless answers scaled by hand
# with mpmath at 60 digits (t_s = t sqrt(m/k), E = m V^2 H_q).
from fractions import Fraction

import mpmath
import pytest

import gyrores


def _close(shown, exact, digits):
    """`shown` (a correct rounding to `digits` digits) lies within half a unit of its last digit."""
    with mpmath.workdps(60):
        exact = mpmath.mpf(exact)
        ulp = mpmath.mpf(10) ** (mpmath.floor(mpmath.log10(abs(exact))) - (digits - 1))
        return abs(mpmath.mpf(shown) - exact) <= ulp / 2 * (1 + mpmath.mpf(10) ** -6)


def test_plant_numbers():
    p = gyrores.plant(mass="0.5", stiffness=200, gyro=4, velocity="0.1", digits=15)
    assert p.n2 == Fraction(4, 25)
    assert p.omega0 == 20.0 and p.time_scale == 0.05
    assert p.energy_scale == Fraction(1, 200) and p.h_q0 == Fraction(1, 400)
    assert p.mass == Fraction(1, 2) and p.units["time"] == "s"
    q = gyrores.plant(mass="0.3", stiffness=200, gyro=3, velocity="0.2", digits=30)
    with mpmath.workdps(60):
        assert _close(q.omega0, mpmath.sqrt(mpmath.mpf(200) / mpmath.mpf("0.3")), 30)
        assert _close(q.time_scale, mpmath.sqrt(mpmath.mpf("0.3") / 200), 30)
    assert q.n2 == Fraction(9, 60)


@pytest.mark.parametrize("m, k, g, V, Ts", [("0.5", "200", "4", "0.1", "2"), ("0.3", "200", "3", "0.2", "1.5")])
def test_plant_coupling_is_the_unit_answer_scaled(m, k, g, V, Ts):
    p = gyrores.plant(mass=m, stiffness=k, gyro=g, velocity=V)
    r = gyrores.coupling(plant=p, horizon_s=Ts, digits=20, convergents=0)
    u = gyrores.coupling(n2=p.n2, horizon=r.horizon, digits=40, convergents=0)
    with mpmath.workdps(60):
        mm, kk, vv = mpmath.mpf(m), mpmath.mpf(k), mpmath.mpf(V)
        assert _close(r.t_min_horizon, u.t_min_horizon * mpmath.sqrt(mm / kk), 20)
        assert _close(r.h_min_horizon, u.h_min_horizon * mm * vv ** 2, 20)
        assert _close(r.r_min_horizon, u.r_min_horizon * vv * mpmath.sqrt(mm / kk), 20)
        # Must fail: the time scaled by sqrt(k/m).
        assert not _close(r.t_min_horizon, u.t_min_horizon * mpmath.sqrt(kk / mm), 20)
    assert r.plant.n2 == p.n2 and r.horizon_s == Ts


def test_plant_is_the_cli(cli_json):
    got = gyrores._gyrores._coupling(None, None, None, "1e-5", 0, 12, None, None, 0, "1", None,
                                     ("0.5", "200", "4", "0.1"), "2")
    assert got == cli_json("coupling", "--mass", "0.5", "--stiffness", "200", "--gyro", "4", "--velocity", "0.1",
                           "--horizon-s", "2", "--below", "1e-5", "--convergents", "0")


def test_qdot0_scales_energies_not_times():
    a = gyrores.coupling(2, horizon=37, below="1e-3", digits=50, convergents=0)
    b = gyrores.coupling(2, horizon=37, below=Fraction(9, 49000), digits=30, convergents=0, qdot0=Fraction(3, 7))
    with mpmath.workdps(60):
        v = mpmath.mpf(3) / 7
        assert _close(b.h_min_horizon, a.h_min_horizon * v ** 2, 30)
        assert _close(b.r_min_horizon, a.r_min_horizon * v, 30)
        assert _close(b.t_min_horizon, a.t_min_horizon, 30) and _close(b.t_below, a.t_below, 30)
    assert b.qdot0 == Fraction(3, 7) and b.below.level == Fraction(1, 1000) and "qdot0" not in a


def test_pair_tolerance_is_the_band_around_its_coupling():
    a = gyrores.coupling(pair=(6, 5), tolerance="1%", horizon=20, convergents=0)
    b = gyrores.coupling(n2="1/30", tolerance="1%", horizon=20, convergents=0)
    assert a.n2 == Fraction(1, 30)
    assert (a.band.n1, a.band.n2) == (b.band.n1, b.band.n2)
    assert a.band.absorption.h_min == b.band.absorption.h_min


def test_plant_tolerance_is_the_band_of_its_n_in_joules_and_seconds():
    p = gyrores.plant(mass="0.3", stiffness=200, gyro=3, velocity="0.2")
    r = gyrores.coupling(plant=p, tolerance="1%", horizon_s="1.5", below="1e-4", convergents=0)
    # The reference: the dimensionless band over the same model horizon at the unit level, at 30
    # digits, scaled by hand with mpmath: E = m V^2 H_q, t_s = t sqrt(m/k).
    u = gyrores.coupling(n2=p.n2, tolerance="1%", horizon=r.horizon, below=r.below.level, convergents=0, band_digits=30)
    assert r.below.level == Fraction(1, 120) and not r.horizon_exact
    assert (r.band.n1, r.band.n2) == (u.band.n1, u.band.n2)
    with mpmath.workdps(60):
        mv2, ts = mpmath.mpf("0.3") * mpmath.mpf("0.2") ** 2, mpmath.sqrt(mpmath.mpf("0.3") / 200)
        for g in ("absorption", "containment"):
            assert _close(r.band[g].h_min, mpmath.mpf(u.band[g].h_min) * mv2, 12)
            assert _close(r.band[g].at.t_min, mpmath.mpf(u.band[g].at.t_min) * ts, 12)
            # Must fail: the energy scaled by m V.
            assert not _close(r.band[g].h_min, mpmath.mpf(u.band[g].h_min) * mpmath.mpf("0.06"), 12)
        assert _close(r.band.first_below.t_below, mpmath.mpf(u.band.first_below.t_below) * ts, 12)
        # Must fail: the time scaled by sqrt(k/m).
        assert not _close(r.band.first_below.t_below, mpmath.mpf(u.band.first_below.t_below) / ts, 12)


def test_plant_tolerance_is_the_cli(cli_json):
    got = gyrores._gyrores._coupling(None, None, None, "1e-5", 0, 12, None, "1%", 0, "1", None,
                                     ("0.5", "200", "4", "0.1"), "2")
    assert got == cli_json("coupling", "--mass", "0.5", "--stiffness", "200", "--gyro", "4", "--velocity", "0.1",
                           "--horizon-s", "2", "--below", "1e-5", "--tolerance", "1%", "--convergents", "0", "--quiet")


@pytest.mark.parametrize("call, message", [
    (lambda: gyrores.plant(mass=-1, stiffness=200, gyro=4, velocity=1), "mass must be > 0"),
    (lambda: gyrores.plant(mass=1, stiffness=0, gyro=4, velocity=1), "stiffness must be > 0"),
    (lambda: gyrores.coupling(0.4, plant=(1, 200, 4, 1)), "drop n"),
    (lambda: gyrores.coupling(plant=(1, 200, 4, 1), qdot0=2), "qdot0"),
    (lambda: gyrores.coupling(plant=(1, 200, 4, 1), band=(0.1, 0.2)), "band is a band of the model's couplings"),
    (lambda: gyrores.coupling(plant=(1, 200, 4, 1), horizon=3, horizon_s=1), "give at most one of horizon \\(model time\\) and horizon_s"),
    (lambda: gyrores.coupling(2, horizon_s=1), "horizon_s"),
    (lambda: gyrores.coupling(2, qdot0=0), "qdot0"),
    (lambda: gyrores.coupling(pair=(6,), tolerance="1%"), "pair"),
])
def test_bad_inputs(call, message):
    with pytest.raises(gyrores.UsageError, match=message):
        call()

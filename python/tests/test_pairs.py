# gyrores.pairs: the batch call over arrays of pairs must give exactly the sweep's rows.
import pytest

import gyrores

np = pytest.importorskip("numpy")


def _same_rows(a, b):
    assert a.dtype == b.dtype and len(a) == len(b)
    for name in a.dtype.names:
        if a[name].dtype.kind == "f":
            assert np.array_equal(a[name], b[name], equal_nan=True), name
        else:
            assert list(a[name]) == list(b[name]), name


def test_pairs_equal_the_sweep_rows():
    rows, _ = gyrores.sweep(811)  # 10^5 pairs
    assert len(rows) >= 10**5
    got = gyrores.pairs(rows["tau"], rows["sigma"])
    _same_rows(rows, got)


def test_pairs_in_any_order_and_from_any_iterable():
    rows, _ = gyrores.sweep(60)
    order = np.random.default_rng(7).permutation(len(rows))
    got = gyrores.pairs(rows["tau"][order].astype(np.int32), list(rows["sigma"][order]), threads=2)
    _same_rows(rows[order], got)
    one = gyrores.pairs((t for t in [6]), iter([5]))
    assert len(one) == 1 and one["r_res"][0] == rows["r_res"][list(zip(rows["tau"], rows["sigma"])).index((6, 5))]
    assert len(gyrores.pairs([], [])) == 0
    # NumPy object arrays of ints (a column of pairs(..., digits=D) with a member beyond int64)
    objects = gyrores.pairs(np.array([6, 9], dtype=object), np.array([5, 4], dtype=object))
    assert list(objects["tau"]) == [6, 9] and objects["r_res"][0] == one["r_res"][0]


def test_certified_pairs_equal_the_certified_sweep():
    # pairs(certified=True): the midpoints of proved enclosures, within a few ulps of the double
    # rows, and every check decided.
    rows, _ = gyrores.sweep(80)
    cert = gyrores.pairs(rows["tau"], rows["sigma"], certified=True)
    ok = ~np.isnan(rows["r_res"])
    assert np.allclose(cert["r_res"][ok], rows["r_res"][ok], rtol=1e-14, atol=0)
    assert (cert["check_degeneracy"] >= 0).all()


@pytest.mark.parametrize("taus, sigmas, message", [
    ([6, 6, 7], [5, 4, 5], r"pairs\(\): \(taus\[1\], sigmas\[1\]\) = \(6, 4\): .*not coprime"),
    ([6], [5, 4], "pairs(): taus and sigmas differ in length"),
    (np.array([6.0]), np.array([5.0]), "pairs(): taus must be a one-dimensional array of integers"),
    ([2**41], [1], r"tau \+ sigma must be <= 2\^40"),
    ([True], [1], "pairs(): taus[0] must be an integer, got a bool"),
])
def test_bad_pairs_raise_usage_error(taus, sigmas, message):
    with pytest.raises(gyrores.UsageError, match=message if "\\" in message or ".*" in message else None) as e:
        gyrores.pairs(taus, sigmas)
    if "\\" not in message and ".*" not in message:
        assert str(e.value).startswith(message)


def test_pairs_with_digits_are_the_proved_values():
    import mpmath
    big = 10**30
    t = gyrores.pairs([6, 9, 11, big + 1], np.array([5, 4, 9, 0], dtype=object) + [0, 0, 0, big], digits=12)
    assert t.dtype["r_res"] == np.float64 and t.dtype["tau"] == object  # 10^30 is beyond int64
    for row in t:
        ref = gyrores.pair(row["tau"], row["sigma"], digits=12)
        assert row["r_res"] == ref.r_res and row["t_first"] == ref.t_first and row["degenerate"] == ref.degenerate
    t40 = gyrores.pairs(np.array([6, 9]), [5, 4], digits=40, threads=2)
    assert isinstance(t40["r_res"][0], mpmath.mpf) and t40["r_res"][0] == gyrores.pair(6, 5, digits=40).r_res
    assert t40.dtype["tau"] == np.int64 and list(t40["minimisers"]) == [2, 2]
    with pytest.raises(gyrores.UsageError, match=r"pairs\(\): \(taus\[1\], sigmas\[1\]\) = \(6, 4\)"):
        gyrores.pairs([6, 6], [5, 4], digits=20)

# gyrores.enumerate_pairs and gyrores.sweep against an independent enumeration and the CLI.
import math
import threading

import pytest

import gyrores


def pairs_up_to(max_order, min_order=3):
    """Coprime tau > sigma >= 1 with min_order <= tau + sigma <= max_order, by order then sigma."""
    return [(a - s, s) for a in range(max(min_order, 3), max_order + 1) for s in range(1, (a + 1) // 2)
            if a - s > s and math.gcd(a - s, s) == 1]


def test_enumerate_pairs_is_lazy_and_exact():
    it = gyrores.enumerate_pairs(10)
    assert iter(it) is it and next(it) == (2, 1)
    assert [(2, 1)] + list(it) == pairs_up_to(10)
    assert sorted(pairs_up_to(10)) == sorted({(t, s) for t in range(1, 11) for s in range(1, t)
                                              if t + s <= 10 and math.gcd(t, s) == 1})
    assert list(gyrores.enumerate_pairs(60, min_order=40)) == pairs_up_to(60, 40)
    assert list(gyrores.enumerate_pairs(2)) == []
    first = next(gyrores.enumerate_pairs(10**12))  # nothing is materialised
    assert first == (2, 1)


def test_sweep_rows_and_summary():
    np = pytest.importorskip("numpy")
    calls = []
    rows, summary = gyrores.sweep(60, progress=lambda done, total: calls.append((done, total)))
    expected = pairs_up_to(60)
    assert [(int(t), int(s)) for t, s in zip(rows["tau"], rows["sigma"])] == expected
    assert summary["pairs"] == len(expected) and calls[-1] == (len(expected), len(expected))
    assert rows.dtype.names[:4] == ("tau", "sigma", "order", "delta_mod4")
    assert not rows["failed"].any() and (rows["order"] == rows["tau"] + rows["sigma"]).all()
    degenerate = rows["delta_mod4"] == 2
    assert (rows["r_res"][degenerate] == 0).all() and (rows["r_res"][~degenerate] > 0).all()
    assert np.isnan(rows["t_first_over_proxy"][degenerate]).all()
    i = expected.index((6, 5))
    assert rows["r_res"][i] == pytest.approx(5.074580579103337e-02, rel=1e-14)


def test_sweep_summary_matches_cli(cli_json):
    _, summary = gyrores.sweep(80, rows=False, checks="default")
    expected = cli_json("sweep", "--max-order", "80", "--quiet")
    assert list(expected["checks"]) == ["degeneracy", "paper-node", "asy-bound", "structure"]
    assert isinstance(summary, gyrores.Result) and isinstance(summary.checks["degeneracy"].examples, tuple)
    # The same JSON with Python's types: Results, tuples, reals as floats (never str: the CLI writes
    # the sweep's doubles as plain decimals, "0.0049966470557269195").
    assert isinstance(summary.asy_ratio_max.value, float) and isinstance(summary.sharp_constant.value, float)
    assert all(isinstance(v, float) for k, v in summary.t_first_over_proxy.items() if k != "count")
    assert summary.asy_ratio_max.value == float(expected["asy_ratio_max"]["value"])
    assert summary.t_first_over_proxy.median == float(expected["t_first_over_proxy"]["median"])
    expected = gyrores._sweep_summary(expected)
    for key in ("pairs", "degenerate", "checks", "errors", "asy_ratio_max", "t_first_over_proxy"):
        assert summary[key] == expected[key], key
    _, everything = gyrores.sweep(80, rows=False, checks="all")
    assert everything["checks"] == summary["checks"]


def test_sweep_rows_known_values():
    np = pytest.importorskip("numpy")
    rows, _ = gyrores.sweep(13, checks="default")
    pairs = [(int(t), int(s)) for t, s in zip(rows["tau"], rows["sigma"])]
    r = {p: i for i, p in enumerate(pairs)}
    assert rows["r_res"][r[(6, 5)]] == pytest.approx(0.0507458057910334, rel=2e-15)
    assert rows["theta_first"][r[(6, 5)]] == pytest.approx(2.9852847488375807, rel=2e-16)
    assert rows["r_res"][r[(9, 4)]] == pytest.approx(0.00871882504953, rel=1e-12)
    assert rows["r_res"][r[(5, 1)]] == pytest.approx(0.0738392921404633, rel=2e-15)
    assert rows["minimiser_count"][r[(5, 1)]] == 4
    assert "check_cross_check" not in rows.dtype.names  # the cross-check is a test of the sources now


def test_sweep_progress_exception_stops_the_sweep():
    class Stop(Exception):
        pass

    def progress(done, total):
        raise Stop()

    with pytest.raises(Stop):
        gyrores.sweep(400, rows=False, progress=progress)


def test_calls_from_several_threads_agree():
    # The GIL is released during library calls, which run in parallel (no shared precision).
    results = {}

    def work(key, fn):
        results[key] = fn()

    threads = [threading.Thread(target=work, args=(i, lambda: gyrores.pair(6, 5, digits=25).to_dict(raw=True)))
               for i in range(3)]
    threads.append(threading.Thread(target=work, args=("sweep", lambda: gyrores.sweep(100, rows=False)[1]["pairs"])))
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert results[0] == results[1] == results[2] and results["sweep"] == len(pairs_up_to(100))


def test_sweep_bad_input():
    with pytest.raises(ValueError, match="max_order"):
        gyrores.sweep(2)
    with pytest.raises(ValueError):
        gyrores.sweep(50, checks="nonsense")


def test_sweep_rows_beyond_memory_are_refused_at_once():
    # order 20000 holds 60,795,197 pairs: ~9.7 GB of rows; refused before any work, naming the way out
    # "at once": no pair is evaluated (the progress callback, called as blocks finish, never runs)
    calls = []
    with pytest.raises(gyrores.UsageError, match=r"sweep\(\): the rows of 60795197 pairs would take about 9\.73 GB.*allow_large=True"):
        gyrores.sweep(20000, progress=lambda done, total: calls.append(done))
    with pytest.raises(gyrores.UsageError, match="allow_large"):
        gyrores.sweep(14000, min_order=0, progress=lambda done, total: calls.append(done))
    assert calls == []
    with pytest.raises(gyrores.UsageError, match="allow_large must be True or False"):
        gyrores.sweep(10, allow_large="yes")
    rows, _ = gyrores.sweep(30, allow_large=True)  # small sweeps are unaffected
    assert len(rows) == gyrores._gyrores._sweep_pairs(3, 30)

# gyrores.certify and gyrores.check: the CLI's certificate, round trips, tampering, the retired /1.
import json
import time
from decimal import Decimal

import pytest

import gyrores


def test_certificate_matches_cli(cli_json, tmp_path):
    import os
    import subprocess
    out = subprocess.run([os.environ["GYRORES_CLI"], "certify", "6", "5", "--digits", "30"], check=True,
                         capture_output=True, text=True).stdout
    assert gyrores.certify(6, 5, digits=30) == json.loads(out)


def test_round_trip_holds_as_dict_text_and_path(tmp_path):
    cert = gyrores.certify(6, 5, digits=30)
    assert cert["format"] == "gyrores-certificate/2" and cert["theorem"] == "lattice-theorem/1"
    # Both ends lie within the 30 digits asked of the independent 40-digit value of r_res.
    for end in cert["claims"]["r_res"]:
        assert abs(Decimal(end) - Decimal("5.074580579103337246371565118651053368385e-02")) <= Decimal("5e-32")
    assert gyrores.check(cert) == {"holds": True, "failure": ""}
    assert gyrores.check(json.dumps(cert)) == {"holds": True, "failure": ""}
    path = tmp_path / "c.json"
    path.write_text(json.dumps(cert))
    assert gyrores.check(path) == {"holds": True, "failure": ""}
    assert gyrores.check(str(path)) == {"holds": True, "failure": ""}


def test_degenerate_and_big_pairs_certify():
    assert gyrores.check(gyrores.certify(11, 9, digits=20)).holds
    big = gyrores.certify(10**30 + 1, 10**30, digits=20)
    assert big["tau"] == str(10**30 + 1) and gyrores.check(big) == {"holds": True, "failure": ""}


def test_retired_cover_certificate_is_refused_at_once():
    # The /1 files that fooled the old checker (Rayleigh t = 1e20: "holds" without running the
    # cover) or kept it busy for hours (all lobes of (10^9, 1)); statements shortened.
    def cover_file(tau, sigma, strategy, t):
        obligations = [
            {"id": "local-root", "statement": "...", "data": {"X_lo": "7.1e-01", "X_hi": "7.2e-01", "j": "0",
                                                               "k": str(sigma), "m": "1"}},
            {"id": "basin", "statement": "...", "data": {"Y_lo": "3.5e-01", "Y_hi": "1.06e+00", "bits": "164"}},
            {"id": "symmetry", "statement": "...", "data": {"images": "2"}},
            {"id": "cover", "statement": "...", "data": {"bits": "164", "bound": "7.9e-62", "boxes": "0", "lobes": "0",
                                                          "strategy": strategy}}]
        if t:
            obligations.append({"id": "rayleigh", "statement": "...", "data": {"t": t}})
        return {"format": "gyrores-certificate/1", "tau": tau, "sigma": sigma, "digits": 20, "working_bits": 164,
                "cover_bits": 164, "degenerate": False, "global_minimality": True,
                "global_minimality_note": "proved (" + strategy + ")",
                "claims": {"r_res": ["2.8e-31", "2.9e-31"], "theta_first": ["3.1e+00", "3.2e+00"],
                           "t_first": ["3.1e+30", "3.2e+30"]},
                "minimiser_count": 2, "obligations": obligations}
    for cert in (cover_file(10**30 + 1, 10**30, "slow-nodes", "1e20"), cover_file(2**64 + 1, 2**64, "slow-nodes", "1e20"),
                 cover_file(10**9, 1, "all-lobes", None)):
        start = time.monotonic()
        with pytest.raises(gyrores.UsageError, match=r"gyrores-certificate/1 .*retired.*"
                                                     r"gyrores certify TAU SIGMA --digits D --out FILE"):
            gyrores.check(cert)
        assert time.monotonic() - start < 1.0
    with pytest.raises(TypeError):
        gyrores.certify(6, 5, digits=20, cover=True)


def test_tampered_certificate_fails():
    cert = gyrores.certify(6, 5, digits=30)
    cert["claims"]["r_res"] = ["5.08e-02", "5.09e-02"]  # excludes the true value
    holds, failure = gyrores.check(cert).values()
    assert not holds and "r_res" in failure


def test_malformed_certificate_raises_value_error(tmp_path):
    cert = gyrores.certify(6, 5, digits=10)
    del cert["claims"]
    with pytest.raises(ValueError, match="malformed certificate"):
        gyrores.check(cert)
    with pytest.raises(ValueError):
        gyrores.check(tmp_path / "missing.json")
    with pytest.raises(ValueError, match="digits must be in"):
        gyrores.certify(6, 5, digits=0)
    with pytest.raises(ValueError, match="not coprime"):
        gyrores.certify(6, 4)

# gyrores.certify and gyrores.check: the CLI's certificate, round trips, tampering.
import json
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
    assert gyrores.check(cert) == (True, "")
    assert gyrores.check(json.dumps(cert)) == (True, "")
    path = tmp_path / "c.json"
    path.write_text(json.dumps(cert))
    assert gyrores.check(path) == (True, "")
    assert gyrores.check(str(path)) == (True, "")


def test_degenerate_and_big_pairs_certify():
    assert gyrores.check(gyrores.certify(11, 9, digits=20))[0]
    big = gyrores.certify(10**30 + 1, 10**30, digits=20)
    assert big["tau"] == str(10**30 + 1) and gyrores.check(big) == (True, "")
    cover = gyrores.certify(6, 5, digits=20, cover=True)
    assert cover["format"] == "gyrores-certificate/1" and gyrores.check(cover) == (True, "")


def test_tampered_certificate_fails():
    cert = gyrores.certify(6, 5, digits=30)
    cert["claims"]["r_res"] = ["5.08e-02", "5.09e-02"]  # excludes the true value
    holds, failure = gyrores.check(cert)
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

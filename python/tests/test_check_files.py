# gyrores.check as `gyrores check`: every certificate format the CLI writes and checks (pair,
# coupling and band certificates), from a path, text, bytes or a dict; reads capped at the CLI's
# 4 MiB; FIFOs and devices refused at once (never waited on); integers of any size in a dict.
import json
import os
import subprocess
import threading
import time

import pytest

import gyrores

LIMIT = 4 << 20  # io/files.hpp, certificate_read_limit


@pytest.fixture(scope="module")
def cli_certificates(tmp_path_factory):
    """Certificates written by the CLI: {name: path}, each accepted by `gyrores check`."""
    cli = os.environ.get("GYRORES_CLI", "")
    if not cli or not os.access(cli, os.X_OK):
        pytest.skip("the gyrores CLI is not built (GYRORES_CLI unset)")
    d = tmp_path_factory.mktemp("certificates")
    made = {
        "pair": ["certify", "6", "5", "--digits", "30", "--out"],
        "coupling never below": ["coupling", "--n2", "1/30", "--horizon", "100", "--below", "1e-4", "--certificate"],
        "coupling below": ["coupling", "2", "--horizon", "50", "--below", "1%", "--certificate"],
        "coupling lobe": ["coupling", "--n2", "1/12", "--horizon", "1e30", "--certificate"],
        "band": ["coupling", "--band", "0.2:0.21", "--horizon", "16", "--below", "1%", "--certificate"],
    }
    paths = {}
    for name, args in made.items():
        path = d / (name.replace(" ", "_") + ".json")
        subprocess.run([cli, *args, str(path)], check=True, capture_output=True)
        subprocess.run([cli, "check", str(path)], check=True, capture_output=True)  # the CLI accepts it
        paths[name] = path
    return paths


@pytest.mark.parametrize("name", ["pair", "coupling never below", "coupling below", "coupling lobe", "band"])
def test_every_certificate_the_cli_accepts_holds_from_path_text_bytes_and_dict(cli_certificates, name):
    path = cli_certificates[name]
    text = path.read_text()
    for cert in (path, str(path), text, text.encode(), json.loads(text)):
        assert gyrores.check(cert) == {"holds": True, "failure": ""}, (name, type(cert).__name__)


@pytest.mark.parametrize("name", ["coupling never below", "coupling lobe", "band"])
def test_a_tampered_coupling_or_band_certificate_is_refused(cli_certificates, name):
    cert = json.loads(cli_certificates[name].read_text())
    # The minimum claimed moves by 1e-6 (far outside its 12-digit enclosure): it must not hold.
    claim = cert["minimum"]["h_min"] if name != "band" else cert["absorption"]["value"]
    claim[:] = [repr(float(t) + 1e-6) for t in claim]
    try:
        verdict = gyrores.check(cert)
    except gyrores.UsageError as e:  # or refused as malformed: either way not accepted
        assert "certificate" in str(e)
    else:
        assert not verdict.holds and verdict.failure


def test_reads_are_capped_at_4_mib_like_the_cli(tmp_path):
    big = tmp_path / "big.json"
    big.write_bytes(b"{" + b" " * LIMIT + b"}")
    start = time.monotonic()
    with pytest.raises(gyrores.UsageError, match=r"larger than 4194304 bytes \(the limit for a certificate\)"):
        gyrores.check(big)
    with pytest.raises(gyrores.UsageError, match="larger than 4194304 bytes"):
        gyrores.check("{" + " " * LIMIT + "}")
    with pytest.raises(gyrores.UsageError, match="larger than 4194304 bytes"):
        gyrores.check({"format": "gyrores-certificate/2", "padding": "x" * LIMIT})
    assert time.monotonic() - start < 5
    # Just under the cap: read, then refused for its content (not for its size).
    small = tmp_path / "small.json"
    small.write_bytes(b"{" + b" " * (LIMIT - 2) + b"}")
    with pytest.raises(gyrores.UsageError, match="malformed"):
        gyrores.check(small)


@pytest.mark.skipif(not os.path.exists("/dev/zero"), reason="no /dev/zero")
def test_devices_are_refused_at_once():
    start = time.monotonic()
    with pytest.raises(gyrores.UsageError, match="'/dev/zero': it is a device, not a regular file"):
        gyrores.check("/dev/zero")
    assert time.monotonic() - start < 1


def test_a_fifo_is_refused_without_waiting_for_a_writer(tmp_path):
    fifo = tmp_path / "cert.fifo"
    os.mkfifo(fifo)
    outcome = []

    def run():
        try:
            gyrores.check(fifo)
        except gyrores.UsageError as e:
            outcome.append(str(e))

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    thread.join(5)
    if thread.is_alive():  # blocked in open(): release it, then fail
        fd = os.open(fifo, os.O_WRONLY)
        os.close(fd)
        thread.join()
        pytest.fail("check() blocked on a FIFO")
    assert outcome and "it is a FIFO, not a regular file" in outcome[0]


def test_directories_missing_files_and_other_arguments(tmp_path):
    with pytest.raises(gyrores.UsageError, match="it is a directory"):
        gyrores.check(tmp_path)
    with pytest.raises(gyrores.UsageError, match="cannot read certificate .*No such file"):
        gyrores.check(tmp_path / "missing.json")
    with pytest.raises(gyrores.UsageError, match="check\\(\\): cert must be a dict, JSON text or a path, got int"):
        gyrores.check(42)
    with pytest.raises(gyrores.UsageError, match="malformed certificate"):
        gyrores.check({"format": "gyrores-certificate/2", "tau": object()})


def test_integers_of_any_size_in_a_dict_are_written_exactly():
    # A dict with an integer beyond Python's 4300-digit int -> text limit reaches the checker
    # (which refuses the pair as too large for a certificate: the integer was read, not lost).
    cert = gyrores.certify(6, 5, digits=20)
    assert gyrores.check(cert).holds
    cert["tau"] = 10**5000 + 1
    with pytest.raises(gyrores.UsageError, match="malformed certificate"):
        gyrores.check(cert)

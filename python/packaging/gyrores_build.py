"""The PEP 517 build backend of gyrores (pyproject.toml): CMake builds the extension, this file
packs it into a wheel. Standard library only, so that ``pip install --no-build-isolation .``
works offline with the Debian packages of scripts/setup (cmake, g++, pybind11-dev, python3-dev,
python3-numpy and the library's own dependencies).

The CMake build tree is a temporary directory, or ``GYRORES_BUILD_DIR`` when set (kept, so a
second install only rebuilds what changed; a tree that is already configured, e.g. the
developer's ``build/``, is used as it is: only its target gyrores_python is brought up to date). ``GYRORES_BUILD_JOBS`` sets the parallel jobs
(default: every core). The interpreter that runs pip is the one the extension is built for.
"""

import base64
import hashlib
import os
import re
import subprocess
import sys
import sysconfig
import tempfile
import zipfile

_SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
_NAME = "gyrores"


def _version():
    """The project version of the top-level CMakeLists.txt (the single source of it)."""
    with open(os.path.join(_SOURCE, "CMakeLists.txt"), encoding="utf-8") as f:
        m = re.search(r"project\(\s*gyrores\s+VERSION\s+([0-9.]+)", f.read())
    if not m:
        raise RuntimeError("gyrores_build: no 'project(gyrores VERSION ...)' in CMakeLists.txt")
    return m.group(1)


def _tag():
    """The wheel tag of this interpreter: e.g. cp311-cp311-linux_x86_64."""
    py = f"cp{sys.version_info.major}{sys.version_info.minor}"
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{py}-{py}-{platform}"


def _metadata():
    return "\n".join([
        "Metadata-Version: 2.1",
        f"Name: {_NAME}",
        f"Version: {_version()}",
        "Summary: Certified, high-precision analysis of energy exchange in gyroscopically coupled oscillators",
        "Requires-Python: >=3.9",
        "Requires-Dist: numpy",
        "Requires-Dist: mpmath",
        "Provides-Extra: plot",
        "Requires-Dist: matplotlib; extra == \"plot\"",
        "",
        "See README.md (section Python) and docs/python.md of the source.",
        "",
    ])


def _wheel_file():
    return "\n".join(["Wheel-Version: 1.0", "Generator: gyrores_build", "Root-Is-Purelib: false", f"Tag: {_tag()}", ""])


def _run(cmd):
    print("gyrores_build:", " ".join(cmd), flush=True)
    subprocess.run(cmd, check=True)


def _build_extension(build_dir):
    """Configures and builds the target gyrores_python; returns the package directory it fills."""
    jobs = os.environ.get("GYRORES_BUILD_JOBS") or str(os.cpu_count() or 1)
    if not os.path.exists(os.path.join(build_dir, "CMakeCache.txt")):
        _run(["cmake", "-S", _SOURCE, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release", "-DGYRORES_BUILD_TESTS=OFF",
              "-DGYRORES_BUILD_BENCH=OFF", "-DGYRORES_BUILD_PROOFS=OFF", f"-DPython3_EXECUTABLE={sys.executable}"])
    _run(["cmake", "--build", build_dir, "--target", "gyrores_python", "-j", jobs])
    package = os.path.join(build_dir, "python", _NAME)
    if not any(n.startswith("_gyrores") and n.endswith(".so") for n in os.listdir(package)):
        raise RuntimeError(f"gyrores_build: the extension was not built in {package} (see CMake's messages above)")
    return package


def _record_line(arcname, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{arcname},sha256={digest},{len(data)}"


def _write_wheel(wheel_directory, package):
    version = _version()
    name = f"{_NAME}-{version}-{_tag()}.whl"
    dist_info = f"{_NAME}-{version}.dist-info"
    files = []
    for entry in sorted(os.listdir(package)):
        path = os.path.join(package, entry)
        if os.path.isfile(path) and (entry.endswith((".py", ".pyi", ".so")) or entry == "py.typed"):
            with open(path, "rb") as f:
                files.append((f"{_NAME}/{entry}", f.read()))
    files.append((f"{dist_info}/METADATA", _metadata().encode()))
    files.append((f"{dist_info}/WHEEL", _wheel_file().encode()))
    records = [_record_line(arc, data) for arc, data in files] + [f"{dist_info}/RECORD,,"]
    files.append((f"{dist_info}/RECORD", ("\n".join(records) + "\n").encode()))
    with zipfile.ZipFile(os.path.join(wheel_directory, name), "w", zipfile.ZIP_DEFLATED) as z:
        for arc, data in files:
            z.writestr(arc, data)
    return name


# PEP 517 hooks --------------------------------------------------------------------------------

def get_requires_for_build_wheel(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    """The wheel's .dist-info without building anything (pip asks for it first)."""
    dist_info = f"{_NAME}-{_version()}.dist-info"
    os.makedirs(os.path.join(metadata_directory, dist_info), exist_ok=True)
    with open(os.path.join(metadata_directory, dist_info, "METADATA"), "w", encoding="utf-8") as f:
        f.write(_metadata())
    with open(os.path.join(metadata_directory, dist_info, "WHEEL"), "w", encoding="utf-8") as f:
        f.write(_wheel_file())
    return dist_info


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    build_dir = os.environ.get("GYRORES_BUILD_DIR")
    if build_dir:
        return _write_wheel(wheel_directory, _build_extension(os.path.abspath(build_dir)))
    with tempfile.TemporaryDirectory(prefix="gyrores-build-") as tmp:
        return _write_wheel(wheel_directory, _build_extension(tmp))


def get_requires_for_build_sdist(config_settings=None):
    return []


def build_sdist(sdist_directory, config_settings=None):
    """The tracked source files (git ls-files) as gyrores-VERSION.tar.gz."""
    import io
    import tarfile
    version = _version()
    base = f"{_NAME}-{version}"
    listed = subprocess.run(["git", "-C", _SOURCE, "ls-files"], check=True, capture_output=True, text=True).stdout
    name = f"{base}.tar.gz"
    with tarfile.open(os.path.join(sdist_directory, name), "w:gz") as tar:
        for rel in listed.splitlines():
            tar.add(os.path.join(_SOURCE, rel), arcname=f"{base}/{rel}")
        info = tarfile.TarInfo(f"{base}/PKG-INFO")
        data = _metadata().encode()
        info.size = len(data)
        tar.addfile(info, io.BytesIO(data))
    return name

"""Executes a notebook (ctest python_notebook): every cell, in a fresh kernel, in a temporary
directory; a failing cell (e.g. an assert) fails the test. Exit 77 (skipped) without nbclient.

Usage: run_notebook.py NOTEBOOK.ipynb. The kernel is Jupyter's "python3" (Debian:
python3-ipykernel); it inherits PYTHONPATH, so it imports the gyrores being tested.
"""
import os
import sys
import tempfile
import time

try:
    import nbclient
    import nbformat
except ImportError:
    print("skipped: nbclient/nbformat not installed (Debian: python3-nbclient python3-ipykernel)")
    sys.exit(77)

os.environ.setdefault("PYDEVD_DISABLE_FILE_VALIDATION", "1")
os.environ.setdefault("MPLBACKEND", "Agg")
path = sys.argv[1]
nb = nbformat.read(path, as_version=4)
start = time.monotonic()
with tempfile.TemporaryDirectory() as work:
    try:
        nbclient.NotebookClient(nb, timeout=600, kernel_name="python3", resources={"metadata": {"path": work}}).execute()
    except nbclient.exceptions.CellExecutionError as e:
        print(f"{path}: a cell failed:\n{e}")
        sys.exit(1)
cells = sum(1 for c in nb.cells if c.cell_type == "code")
print(f"{path}: {cells} code cells executed in {time.monotonic() - start:.1f} s")

"""The same data and options give a bit-identical ``loop.json`` on one install (issue 18).

Whatever the core count, the thread count, the hash seed and the load: the loop is run
twice in subprocesses, once pinned to one core on one BLAS/OpenMP thread and once on
every core with two threads and another process burning a core beside it, and the two
``loop.json`` are compared byte for byte (the file holds no date or timing; those are in
``provenance.json``).

Across processors the numbers may move: numpy picks its SIMD kernels (AVX2 or
AVX-512) at run time, and ``exp``/``log``/``power`` then differ in the last bit for
a few per cent of their arguments. The last test runs the golden ``synth`` + ``loop``
with numpy's AVX-512 kernels switched off (where the processor has them) and checks
that the result stays within the golden tolerances of ``golden.TOLERANCES``, which
are stated from the solvers' own convergence tolerances.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

import golden  # noqa: E402

SYNTH = ["synth", "--effect", "seal_coulomb_friction", "--seed", "3", "--out", "synth_seal.csv"]
LOOP = ["loop", "synth_seal.csv", "--out", "loop_seal", "--json", "--no-figures"]
THREAD_VARS = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")


def _one_core() -> None:  # pragma: no cover - runs in the child
    if hasattr(os, "sched_setaffinity"):
        os.sched_setaffinity(0, {min(os.sched_getaffinity(0))})


def _oilgap(argv: list[str], cwd: Path, one_core: bool = False, **env: str) -> None:
    full = {**os.environ, **env}
    r = subprocess.run([sys.executable, "-m", "oilgap.cli", *argv], cwd=cwd, env=full,
                       capture_output=True, text=True, timeout=300,
                       preexec_fn=_one_core if one_core else None)
    assert r.returncode == 0, r.stderr


def _threads(n: int) -> dict[str, str]:
    return dict.fromkeys(THREAD_VARS, str(n))


@pytest.fixture(scope="module")
def synth_dir(tmp_path_factory) -> Path:
    d = tmp_path_factory.mktemp("synth")
    _oilgap(SYNTH, d)
    return d


def _loop_in(d: Path, synth: Path, one_core: bool = False, **env: str) -> bytes:
    d.mkdir()
    (d / "synth_seal.csv").write_bytes((synth / "synth_seal.csv").read_bytes())
    _oilgap(LOOP, d, one_core, **env)
    return (d / "loop_seal" / "loop.json").read_bytes()


def test_loop_json_is_bit_identical_across_threads_hash_seed_and_load(synth_dir, tmp_path):
    one = _loop_in(tmp_path / "one", synth_dir, one_core=True, PYTHONHASHSEED="0", **_threads(1))
    burner = subprocess.Popen([sys.executable, "-c", "import time\nt = time.time()\n"
                               "while time.time() - t < 120: pass"])
    try:
        two = _loop_in(tmp_path / "two", synth_dir, PYTHONHASHSEED="12345", **_threads(2))
    finally:
        burner.kill()
        burner.wait()
    assert b'"seal_coulomb_friction"' in one  # the loop found the injected effect
    assert one == two


def _avx512_targets() -> list[str]:
    """numpy's AVX-512 dispatch targets that this processor runs (their names vary by version)."""
    try:
        from numpy._core._multiarray_umath import __cpu_dispatch__, __cpu_features__
    except ImportError:  # pragma: no cover - numpy < 2
        return []
    return [f for f in __cpu_dispatch__ if ("AVX512" in f or f == "X86_V4")
            and __cpu_features__.get(f)]


@pytest.mark.skipif(not _avx512_targets(), reason="no AVX-512 kernels to switch off here")
def test_other_simd_kernels_stay_within_the_golden_tolerance(tmp_path):
    off = {"NPY_DISABLE_CPU_FEATURES": " ".join(_avx512_targets())}
    _oilgap(SYNTH, tmp_path, **off)
    _oilgap(LOOP, tmp_path, **off)
    rel = "loop_seal/loop.json"
    want = json.loads((golden.DATA / rel).read_text())
    got = json.loads((tmp_path / rel).read_text())
    assert not golden.compare_json(want, got, rel, rel)
    md = "loop_seal/report.md"
    assert not golden.compare_text((golden.DATA / md).read_text(),
                                   (tmp_path / md).read_text(), md)

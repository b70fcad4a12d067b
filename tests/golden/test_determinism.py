"""The same data and options give the same ``loop.json`` on one install, whatever the core
count, the thread count, the hash seed and the load (issue 18), to what the solvers
determine (issue 26).

The loop is run twice in subprocesses, once pinned to one core on one BLAS/OpenMP thread
and once on every core with two threads, another hash seed and another process burning a
core beside it. The two ``loop.json`` are compared as the golden test compares them
(``golden.compare_json`` with ``golden.TOLERANCES``): every word, every effect chosen and
every count exactly; every number to the tolerance of the solver that made it. Not byte
for byte: OpenBLAS splits its sums by thread count, and on some data (the synthetic rig
written on a processor without AVX-512) that moves the fitted parameters by ~5e-12 and a
held-out gain that is zero, -2.80e-11 % on one thread, to -2.84e-11 % on two. Such a
quantity is undetermined below the fit's ``ftol``; it is compared with the absolute
tolerance of its row (``RESIDUAL_ATOL``).

Across processors the numbers move too: numpy picks its SIMD kernels (AVX2 or AVX-512)
and OpenBLAS its kernels (Haswell or SkylakeX) at run time, and ``exp``/``log``/``power``
then differ in the last bit for a few per cent of their arguments. The last test runs the
golden ``synth`` + ``loop`` as a processor without AVX-512 would
(``golden.without_avx512_env``) and checks the result against the golden tolerances.
``.ci/run`` also runs every golden test a second time that way.
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
LOOP = ["loop", "synth_seal.csv", "--out", "loop_seal", "--json", "--no-figures", "--base",
        "eq6"]  # as golden.py's loop_seal
THREAD_VARS = golden.THREAD_VARS
REL = "loop_seal/loop.json"


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


def test_loop_json_is_the_same_across_threads_hash_seed_and_load(synth_dir, tmp_path):
    one = _loop_in(tmp_path / "one", synth_dir, one_core=True, PYTHONHASHSEED="0", **_threads(1))
    burner = subprocess.Popen([sys.executable, "-c", "import time\nt = time.time()\n"
                               "while time.time() - t < 120: pass"])
    try:
        two = _loop_in(tmp_path / "two", synth_dir, PYTHONHASHSEED="12345", **_threads(2))
    finally:
        burner.kill()
        burner.wait()
    assert b'"seal_coulomb_friction"' in one  # the loop found the injected effect
    diffs = golden.compare_json(json.loads(one), json.loads(two), REL, REL)
    assert not diffs, "\n".join(diffs[:20])


def test_what_is_determined_is_compared_and_a_zero_is_not():
    """The comparison of the test above on the numbers of issue 26: the held-out gain of an
    effect that adds nothing is -2.80442e-11 % on one machine and -2.84439e-11 % on
    another (equal within RESIDUAL_ATOL); the seal friction changed in its 7th digit
    or an effect chosen differently is a difference."""
    doc = {"effects": [{"name": "seal_coulomb_friction", "heldout_gain_added_pct": -2.80442e-11}],
           "model": {"effects": {"seal_coulomb_friction": 0.04023165056948135}}}
    zero = json.loads(json.dumps(doc).replace("-2.80442e-11", "-2.84439e-11"))
    assert not golden.compare_json(doc, zero, REL, REL)
    moved = json.loads(json.dumps(doc).replace("0.04023165056948135", "0.04023175056948135"))
    assert golden.compare_json(doc, moved, REL, REL)
    other = json.loads(json.dumps(doc).replace('"name": "seal', '"name": "viscous'))
    assert golden.compare_json(doc, other, REL, REL)


@pytest.mark.skipif(not golden.avx512_targets(), reason="no AVX-512 kernels to switch off here")
def test_other_simd_kernels_stay_within_the_golden_tolerance(tmp_path):
    off = golden.without_avx512_env()
    _oilgap(SYNTH, tmp_path, **off)
    _oilgap(LOOP, tmp_path, **off)
    want = json.loads((golden.DATA / REL).read_text())
    got = json.loads((tmp_path / REL).read_text())
    assert not golden.compare_json(want, got, REL, REL)
    md = "loop_seal/report.md"
    assert not golden.compare_text((golden.DATA / md).read_text(),
                                   (tmp_path / md).read_text(), md)

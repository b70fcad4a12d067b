"""The one JSON/TOML writer: 6 significant digits, NaN as null, the fitted model in full,
and case files written by tomli-w that read back to the same case."""

import json
import math
import tomllib
from dataclasses import replace

import numpy as np
import pytest

from oilgap.model.io.case_io import read_case_toml, seed_case
from oilgap.model.io.case_write import case_to_dict
from oilgap.model.io.serialize import Exact, dumps, round_sig, toml_dumps
from oilgap.studies.io.case_write import write_case_toml


def test_round_sig_by_hand():
    assert round_sig(3000.0000000000005) == 3000.0
    assert round_sig(37.713312256684894) == 37.7133
    assert round_sig(-0.000123456789) == -0.000123457
    assert round_sig(6.84103124833428e-05) == 6.84103e-05
    assert round_sig(0.0) == 0.0 and math.isinf(round_sig(math.inf))


def test_dumps_rounds_and_writes_nan_as_null():
    doc = {"a_W": 0.1 + 0.2, "b": [np.float64(1 / 3), np.int64(7), np.nan],
           "c": np.array([2.0000000001, -math.inf]), "ok": np.bool_(True), "s": "x"}
    text = dumps(doc, indent=None)
    assert json.loads(text) == {"a_W": 0.3, "b": [0.333333, 7, None], "c": [2.0, None],
                                "ok": True, "s": "x"}
    assert "NaN" not in text and "Infinity" not in text


def test_exact_blocks_keep_every_digit():
    x = 0.1 + 0.2
    back = json.loads(dumps({"rounded": x, "model": Exact({"coef": [x, 1 / 3]})}))
    assert back["rounded"] == 0.3
    assert back["model"]["coef"] == [x, 1 / 3]  # the same doubles
    assert json.loads(json.dumps(Exact({"k": 1}))) == {"k": 1}  # still a plain dict


def test_toml_dumps_rounds_and_leaves_out_none():
    text = toml_dumps({"name": "j", "region1": {"T1_mm": 37.713312256684894, "x": None}})
    assert "T1_mm = 37.7133" in text and "x =" not in text
    assert tomllib.loads(text) == {"name": "j", "region1": {"T1_mm": 37.7133}}


def _close(a, b, rel):
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(_close(a[k], b[k], rel) for k in a)
    if isinstance(a, list):
        return len(a) == len(b) and all(_close(x, y, rel) for x, y in zip(a, b, strict=True))
    if isinstance(a, float):
        return a == pytest.approx(b, rel=rel, abs=1e-300)
    return a == b


def test_written_case_reads_back_to_the_same_case(tmp_path):
    # an optimizer-like design: radii with 17 digits, a mission, a thermal table
    seed = seed_case()
    r1 = seed.region1
    case = replace(seed, name="noisy", region1=replace(
        r1, T1=23.847260655861670e-3, T2=23.847260655861670e-3, T3=25.508463894091180e-3,
        T4=25.508463894091180e-3, length=19.999999999999996e-3,
        T1_unfilled=22.347260655861670e-3, T4_unfilled=27.008463894091180e-3))
    path = write_case_toml(case, tmp_path / "c.toml")
    text = path.read_text()
    assert text.startswith("# written by oilgap ") and " by: " in text.splitlines()[0]
    assert "T1_mm = 23.8473\n" in text and "length_mm = 20.0\n" in text
    back = read_case_toml(path)
    # every key's value to its 6 significant digits: relative error <= 5e-6
    assert _close(case_to_dict(back), case_to_dict(case), rel=5e-6)
    assert back.region1.gap == pytest.approx(case.region1.gap, abs=1e-7)  # 0.1 um
    # and a case whose numbers are short comes back exactly
    again = read_case_toml(write_case_toml(seed, tmp_path / "s.toml", header=False))
    assert case_to_dict(again) == case_to_dict(seed)
    assert not (tmp_path / "s.toml").read_text().startswith("#")

"""Issue 18: no two commands print different losses for the same design under their
defaults (the NLP's smooth C_m aside, printed beside the exact value).

For the seed joint, ``examples/my_joint.toml`` (with a ``[thermal]`` table: the default
is ``bulk``) and the README's ``my_joint.toml`` (without: ``none``), the case's own design
at its rated point is read from every place that reports it: ``oilgap evaluate --json``,
``og.evaluate``, ``og.optimize``'s initial design (exact C_m), ``og.pareto``'s marked
design (exact C_m) and ``og.oil_grade`` at the rated point. All must agree, and so must
the film band each prints beside it. The seed's number is the seed paper's isothermal
value, 49.45 W (its Sec. IV; ``oilgap evaluate --thermal none`` before issue 18).
"""

import json
import re
from pathlib import Path

import pytest

import oilgap as og
from oilgap.cli import main

ROOT = Path(__file__).resolve().parents[2]
README_CASE = re.search(r"`my_joint.toml`:\n\n```toml\n(.*?)```",
                        (ROOT / "README.md").read_text(), re.S).group(1)
JSON_REL = 1e-5  # the JSON carries 6 significant digits (oilgap.model.io.serialize)
SEED_PAPER_W = 49.45  # the seed paper's isothermal mean loss at the rated point [W]


@pytest.fixture(scope="module")
def readme_case(tmp_path_factory):
    path = tmp_path_factory.mktemp("readme") / "my_joint.toml"
    path.write_text(README_CASE)
    return str(path)


def _cases(readme_case):
    return {"seed": None, "example": str(ROOT / "examples" / "my_joint.toml"),
            "readme": readme_case}


@pytest.mark.parametrize("which, mode", [("seed", "none"), ("example", "bulk"),
                                         ("readme", "none")])
def test_every_command_prints_the_same_loss_under_its_default(capsys, readme_case, which,
                                                              mode):
    case = _cases(readme_case)[which]
    assert main(["evaluate", "--json", *([case] if case else [])]) == 0
    cli = json.loads(capsys.readouterr().out)
    ev = og.evaluate(case)
    opt = og.optimize(case, starts=1).to_dict()
    par = og.pareto(case, points=50)
    grade = og.oil_grade(case, n_depth=3, n_temp=3)
    own = par.raw.seeds.iloc[0]  # the seed (T = 4) or "this design"
    assert (cli["thermal_mode"], ev.thermal_mode, opt["thermal_mode"], par.raw.thermal_mode,
            grade.raw.thermal_mode) == (mode,) * 5
    p = ev.total_mean_power_W
    assert cli["total_mean_power_W"] == pytest.approx(p, rel=JSON_REL)
    assert opt["initial"]["mean_power_exact_W"] == pytest.approx(p, rel=1e-12)
    assert own["mean_power_exact_W"] == pytest.approx(p, rel=1e-12)
    assert grade.raw.film_band.mean_power_W == pytest.approx(p, rel=1e-12)
    name = og.read_case(case).oil.name if case else "VG22"
    rated = grade.raw.table.set_index("oil").loc[name, "rated_power_W"]
    assert rated == pytest.approx(p, rel=1e-12)
    # the smooth C_m of the NLP, printed beside: within 0.1 % of the exact value
    assert opt["initial"]["mean_power_W"] == pytest.approx(p, rel=1e-3)
    assert own["mean_power_W"] == pytest.approx(p, rel=1e-3)
    # the film band beside it: the same number everywhere
    band = ev.raw.film_band
    assert band.other_mode == {"none": "film", "bulk": "full"}[mode]
    assert cli["film_band"]["mean_power_W"] == pytest.approx(band.other_mean_power_W,
                                                             rel=JSON_REL)
    assert opt["initial"]["film_band"]["mean_power_W"] == pytest.approx(
        band.other_mean_power_W, rel=1e-12)
    assert own["film_band_power_W"] == pytest.approx(band.other_mean_power_W, rel=1e-12)
    assert grade.raw.film_band.other_mean_power_W == pytest.approx(band.other_mean_power_W,
                                                                   rel=1e-12)
    assert band.other_mean_power_W < p  # film heating lowers the loss
    if which == "seed":
        assert p == pytest.approx(SEED_PAPER_W, abs=5e-3)

"""Output hygiene: --version, -v/-q through logging, provenance.json in every result
folder and a stamp on a written case, one unit convention in every JSON key."""

import hashlib
import json
import logging
import re
from datetime import UTC, datetime
from importlib.metadata import version
from pathlib import Path

import pytest

import oilgap
from oilgap.cli import LOG, build_parser, configure_logging, main
from oilgap.model.io.case_io import seed_case
from oilgap.model.io.case_write import case_to_dict, dumps_toml
from oilgap.studies.outputs import OUTPUTS

NOMENCLATURE = Path(__file__).parents[2] / "docs" / "nomenclature.md"


def sha256(path) -> str:
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


@pytest.fixture
def bearing_case(tmp_path):
    p = tmp_path / "bearing.toml"
    p.write_text(dumps_toml(case_to_dict(seed_case())) + '\n[bearing]\ndesignation = "61808"\n')
    return p


def test_version(capsys):
    assert main(["--version"]) == 0
    assert capsys.readouterr().out == f"oilgap {version('oilgap')}\n"
    assert oilgap.__version__ == version("oilgap")


def test_no_command_is_refused_with_exit_2(capsys):
    with pytest.raises(SystemExit) as e:
        main([])
    assert e.value.code == 2 and "COMMAND" in capsys.readouterr().err


@pytest.mark.parametrize("argv, verbose, quiet", [
    (["-v", "evaluate"], 1, False), (["evaluate", "-v"], 1, False),
    (["-vv", "optimize"], 2, False), (["-q", "study", "sweep", "g.csv"], 0, True),
    (["study", "pareto", "-q"], 0, True), (["study", "-q", "oil-grade"], 0, True),
    (["loop", "d.csv", "--quiet"], 0, True), (["evaluate"], 0, False)])
def test_verbosity_before_or_after_the_command(argv, verbose, quiet):
    args = build_parser().parse_args(argv)
    assert (args.verbose, args.quiet) == (verbose, quiet)


def test_v_and_q_exclude_each_other(capsys):
    with pytest.raises(SystemExit) as e:
        main(["evaluate", "-v", "-q"])
    assert e.value.code == 2


def test_logger_levels(capsys):
    for kw, shown in (({"quiet": True}, ["oilgap: w"]),
                      ({}, ["oilgap: i", "oilgap: w"]),
                      ({"verbose": 1}, ["oilgap: d", "oilgap: i", "oilgap: w"])):
        configure_logging(**kw)
        LOG.debug("d")
        LOG.info("i")
        LOG.warning("w")
        assert capsys.readouterr().err.splitlines() == shown
    configure_logging()
    # one handler of oilgap's however often configured (pytest >= 9.2 adds its own capture
    # handlers to a logger that does not propagate: not counted)
    assert len([h for h in LOG.handlers if isinstance(h, logging.StreamHandler)
                and type(h).__module__.startswith("oilgap")]) == 1


def test_quiet_keeps_warnings_verbose_names_inputs(tmp_path, capsys, bearing_case):
    # a warning that changes the result survives -q, in its usual form
    assert main(["-q", "evaluate", "--temp-c", "-35", "--json"]) == 0
    cap = capsys.readouterr()
    assert json.loads(cap.out)["oil_temp_C"] == -35
    assert cap.err.startswith("oilgap: warning: oil_temp_C = -35") and "command:" not in cap.err
    # -v: the command, the versions, the input with its SHA-256, the time taken
    assert main(["evaluate", str(bearing_case), "-v", "--json"]) == 0
    err = capsys.readouterr().err
    assert f"oilgap: input case: {bearing_case} (sha256 {sha256(bearing_case)})" in err
    assert f"oilgap {version('oilgap')}, python" in err and f"numpy {version('numpy')}" in err
    assert re.search(r"oilgap: evaluate took \d+\.\d+ s", err)
    configure_logging()


def test_every_folder_command_lists_provenance():
    assert all("provenance.json" in files for files in OUTPUTS.values())


def test_sweep_folder_carries_provenance(tmp_path, capsys, bearing_case):
    grid = tmp_path / "g.csv"
    grid.write_text("gap_mm,oil\n0.8,VG22\n1.2,VG46\n")
    out = tmp_path / "sw"
    argv = ["study", "sweep", str(grid), "--case", str(bearing_case), "--out", str(out),
            "--workers", "1", "--thermal", "none", "-q"]
    before = datetime.now(UTC).replace(microsecond=0)
    assert main(argv) == 0
    assert capsys.readouterr().err == ""  # -q: no progress, no notes
    text = (out / "provenance.json").read_text()
    p = json.loads(text)
    assert p["oilgap_version"] == version("oilgap") and p["command"] == ["oilgap", *argv]
    when = datetime.strptime(p["created_utc"], "%Y-%m-%dT%H:%M:%SZ").replace(tzinfo=UTC)
    assert before <= when <= datetime.now(UTC)
    assert p["inputs"] == {
        "case": {"path": str(bearing_case.resolve()), "bytes": bearing_case.stat().st_size,
                 "sha256": sha256(bearing_case)},
        "grid": {"path": str(grid.resolve()), "bytes": grid.stat().st_size,
                 "sha256": sha256(grid)}}
    assert p["packages"] == {n: version(n) for n in ("numpy", "scipy", "casadi", "pandas")}
    assert p["thermal_mode_asked"] == "none"
    assert (p["gamma"], p["gamma_source"]) == (seed_case().friction.gamma, "case")
    # --force replaces it with the new run's
    assert main([*argv, "--force"]) == 0
    assert json.loads((out / "provenance.json").read_text())["command"][-1] == "--force"


def test_optimize_out_is_stamped(tmp_path, capsys):
    out = tmp_path / "opt.toml"
    assert main(["optimize", "--starts", "1", "--out", str(out), "-q"]) == 0
    first, second = out.read_text().splitlines()[:2]
    assert first.startswith(f"# written by oilgap {version('oilgap')} on ")
    assert first.endswith(f"by: oilgap optimize --starts 1 --out {out} -q")
    assert second.startswith("name = ")
    # every digit of the optimum (issue 26): tests/cli/test_answer_first.py evaluates the
    # file again and finds the loss optimize printed


# ---------------------------------------------------------------- one unit convention


def _convention():
    """The suffixes and the dimensionless names of docs/nomenclature.md."""
    text = NOMENCLATURE.read_text(encoding="utf-8").split("## Units at the edges")[1]
    suffixes = re.findall(r"^\| `(_[^`]+)`(?:, `(_[^`]+)`)? \|", text, re.M)
    dimensionless = re.search(r"<!-- dimensionless: ([^>]*) -->", text).group(1).split()
    return {s for pair in suffixes for s in pair if s}, set(dimensionless)


def _unitless(doc, suffixes, dimensionless, path="", parent_unit=False):
    """Keys of numbers with neither a unit suffix nor a documented reason (a table under
    a key with a unit or a dimensionless name holds values of that key)."""
    bad = []
    items = doc.items() if isinstance(doc, dict) else enumerate(doc) \
        if isinstance(doc, list) else ()
    has_unit_field = isinstance(doc, dict) and "unit" in doc
    for k, v in items:
        key = k if isinstance(k, str) else ""
        if key == "defaults":
            continue  # case-file units, listed in docs/case-file.md
        unit = any(key.endswith(s) for s in suffixes)
        if isinstance(v, (int, float)) and not isinstance(v, bool):
            if not (unit or key in dimensionless or parent_unit or has_unit_field
                    or not key):
                bad.append(f"{path}/{key}")
        else:
            bad += _unitless(v, suffixes, dimensionless, f"{path}/{k}",
                             parent_unit=unit or key in dimensionless
                             or (parent_unit and not key))
    return bad


def test_json_keys_carry_their_units(capsys, bearing_case, tmp_path):
    suffixes, dimensionless = _convention()
    assert {"_mm", "_W", "_rpm", "_cSt", "_C", "_Nm", "_kgm2"} <= suffixes
    docs = {}
    for name, argv in (("evaluate", ["evaluate", "--json"]),
                       ("evaluate bearing", ["evaluate", str(bearing_case), "--json"]),
                       ("optimize", ["optimize", "--json", "--starts", "1"]),
                       ("optimize none", ["optimize", "--json", "--starts", "1",
                                          "--thermal", "none"]),
                       ("uncertainty", ["study", "uncertainty", "--json", "--samples", "64",
                                        "--sobol-samples", "32", "--out",
                                        str(tmp_path / "u")])):
        assert main(argv) == 0
        docs[name] = json.loads(capsys.readouterr().out)
    region = docs["evaluate"]["regions"][0]
    assert (region["radius_mm"], region["gap_mm"], region["length_mm"]) == (25.4, 1.0, 14.76)
    assert docs["evaluate bearing"]["bearings"][0]["pitch_diameter_mm"] == 46.0
    for name, doc in docs.items():
        assert _unitless(doc, suffixes, dimensionless) == [], name
    # and the walk does find a key without a unit
    assert _unitless({"a": {"gap": 1.0}}, suffixes, dimensionless) == ["/a/gap"]

"""Provenance as a record the caller passes in: what it names, and that it reads no case.

The hash is checked against hashlib on the bytes written here; the case named by a run
is never parsed (a file that is not TOML is recorded by its hash alone).
"""

from __future__ import annotations

import hashlib
import sys

from oilgap.studies.io.provenance import RunRecord, provenance, stamp_line


def test_a_command_lines_record_names_its_command_and_inputs(tmp_path):
    case = tmp_path / "case.toml"
    data = b"this is not TOML [[["  # a case that cannot be read: provenance never parses it
    case.write_bytes(data)
    run = RunRecord.command_line(["study", "sweep", "g.csv"], {"case": case},
                                 thermal_mode_asked="none")
    doc = provenance(run, thermal_mode="bulk")
    assert doc["command"] == ["oilgap", "study", "sweep", "g.csv"]
    assert doc["inputs"] == {"case": {"path": str(case.resolve()), "bytes": len(data),
                                      "sha256": hashlib.sha256(data).hexdigest()}}
    assert (doc["thermal_mode_asked"], doc["thermal_mode"]) == ("none", "bulk")
    assert "gamma" not in doc  # the code that read the case notes its gamma, not this
    assert stamp_line(run=run).endswith("by: oilgap study sweep g.csv")


def test_details_given_when_writing_override_the_records():
    run = RunRecord(argv=("oilgap", "loop"), details={"thermal_mode_asked": "default"})
    assert provenance(run, thermal_mode_asked="film")["thermal_mode_asked"] == "film"
    assert run.details == {"thermal_mode_asked": "default"}  # the record is not changed


def test_a_run_from_python_names_sys_argv_and_no_inputs(tmp_path):
    doc = provenance()
    assert doc["command"] == ["oilgap-python", *sys.argv] and doc["inputs"] == {}
    assert stamp_line().endswith("by: " + " ".join(["python", *sys.argv]))


def test_an_unreadable_input_is_named_with_its_reason(tmp_path):
    doc = provenance(RunRecord(argv=("oilgap",), inputs={"grid": str(tmp_path / "gone")}))
    assert doc["inputs"]["grid"]["error"] and "sha256" not in doc["inputs"]["grid"]

"""Bad input values and unreadable input files at the command line (issue 12): each is
refused with exit 2 and exactly one line on stderr naming the field, no traceback, and
nothing written. In-process ``main([...])`` calls."""

import errno
from pathlib import Path

import pytest

from oilgap.cli import main
from oilgap.model.io import inputs

CASE = """name = "t"
[region1]
T1_mm = 23.9
T2_mm = 25.4
T3_mm = 26.4
T4_mm = 27.9
length_mm = 14.76
[friction]
gamma = 0.566
"""

SECRET_LINE = "root:x:0:0:hunter2-secret:/root:/bin/bash"


def case(tmp_path: Path, extra: str = "", replace: tuple[str, str] = ("", ""),
         name: str = "case.toml") -> str:
    p = tmp_path / name
    text = CASE.replace(*replace) if replace[0] else CASE
    p.write_text(text + extra)
    return str(p)


def files(tmp_path: Path) -> set[Path]:
    return set(tmp_path.rglob("*"))


def refuses(tmp_path, capsys, argv, *words, absent=()):
    before = files(tmp_path)
    capsys.readouterr()
    assert main(argv) == 2
    cap = capsys.readouterr()
    lines = cap.err.strip().splitlines()
    assert len(lines) == 1, cap.err
    assert lines[0].startswith("oilgap: error:") and "Traceback" not in cap.err
    for w in words:
        assert w in lines[0], lines[0]
    for w in absent:
        assert w not in cap.err + cap.out
    assert files(tmp_path) == before, "something was written"
    return lines[0]


# --------------------------------------------------------------------------- case values

CASE_VALUES = [
    ("gamma 1e300", {"replace": ("gamma = 0.566", "gamma = 1e300")}, ["gamma", "[0, 3]"]),
    ("gamma negative", {"replace": ("gamma = 0.566", "gamma = -0.5")}, ["gamma"]),
    ("peak 1e300", {"extra": "[duty_cycle]\npeak_speed_rpm = 1e300\n"}, ["peak_speed_rpm"]),
    ("power-law beta 1000", {"replace": ("gamma = 0.566", 'gamma = 0.566\nform = "power-law"'
                                         "\nbeta = 1000")}, ["beta"]),
    ("7 TiB duty cycle", {"extra": "[duty_cycle]\nduration_s = 1e9\nsample_interval_s = 0.001\n"},
     ["duration_s", "1e+12 samples"]),
    ("100000 slots", {"extra": "[motor]\nslot_count = 100000\nslot_opening_mm = 1e6\n"},
     ["slot_count"]),
    ("slot wider than pitch", {"extra": "[motor]\nslot_count = 1000\nslot_opening_mm = 1.0\n"},
     ["slot_opening_mm", "slot pitch"]),
    ("1 km gap", {"replace": ("T3_mm = 26.4\nT4_mm = 27.9", "T3_mm = 1e6\nT4_mm = 1.1e6")},
     ["T3_mm"]),
    ("thin oil", {"extra": '[oil]\nname = "thin"\nnu40_cSt = 0.2\nnu100_cSt = 0.1\n'
                           "density_kg_m3 = 800\n"}, ["nu40_cSt", "Walther"]),
]


@pytest.mark.parametrize("label,kw,words", CASE_VALUES, ids=[c[0] for c in CASE_VALUES])
def test_case_value_refused(tmp_path, capsys, label, kw, words):
    refuses(tmp_path, capsys, ["evaluate", case(tmp_path, **kw)], *words)


# --------------------------------------------------------------------------- input files


def test_duty_cycle_csv_not_utf8(tmp_path, capsys):
    (tmp_path / "cyc.csv").write_bytes(b"time_s,speed_rpm\n0,\xff\xfe\n1,3\n")
    p = case(tmp_path, '[duty_cycle]\ncsv = "cyc.csv"\n')
    refuses(tmp_path, capsys, ["evaluate", p], "duty_cycle.csv", "not UTF-8")


def test_duty_cycle_csv_is_a_directory(tmp_path, capsys):
    (tmp_path / "cyc.csv").mkdir()
    p = case(tmp_path, '[duty_cycle]\ncsv = "cyc.csv"\n')
    refuses(tmp_path, capsys, ["evaluate", p], "duty_cycle.csv", "is a directory")


def test_case_is_a_directory(tmp_path, capsys):
    (tmp_path / "case.toml").mkdir()
    refuses(tmp_path, capsys, ["evaluate", str(tmp_path / "case.toml")], "case",
            "is a directory")


@pytest.mark.parametrize("err,words", [(errno.EIO, "input/output error"),
                                       (errno.EACCES, "permission denied")])
def test_unreadable_case_file(tmp_path, capsys, monkeypatch, err, words):
    p = case(tmp_path)

    def fail(*a, **k):
        raise OSError(err, "boom")
    monkeypatch.setattr(inputs, "open", fail, raising=False)
    refuses(tmp_path, capsys, ["evaluate", p], "case", words, str(p))


def test_unreadable_oils_file(tmp_path, capsys, monkeypatch):
    oils = tmp_path / "oils.csv"
    oils.write_text("oil,nu40_cSt,nu100_cSt,density_kg_m3\nX,22,4.5,860\n")
    p = case(tmp_path, f'[oil]\nname = "X"\noils_csv = "{oils.name}"\n')

    def fail(path, *a, **k):
        if Path(path).suffix == ".csv":
            raise OSError(errno.EIO, "boom")
        return open(path, *a, **k)
    monkeypatch.setattr(inputs, "open", fail, raising=False)
    refuses(tmp_path, capsys, ["evaluate", p], "oil.oils_csv", "input/output error")


def test_oils_csv_pointing_at_another_file_is_not_echoed(tmp_path, capsys):
    secret = tmp_path / "passwd"
    secret.write_text(SECRET_LINE + "\n")
    p = case(tmp_path, f'[oil]\nname = "VG22"\noils_csv = "{secret}"\n')
    refuses(tmp_path, capsys, ["evaluate", p], "columns", str(secret),
            absent=("hunter2", "root:x"))
    refuses(tmp_path, capsys, ["evaluate", "--oil", "VG22", "--oils", str(secret)], "columns",
            absent=("hunter2", "root:x"))


def test_case_file_that_is_not_a_case_is_not_echoed(tmp_path, capsys):
    p = tmp_path / "settings.toml"
    p.write_text('[database]\npassword = "hunter2"\n')
    refuses(tmp_path, capsys, ["evaluate", str(p)], "database", "unknown key",
            absent=("hunter2",))


# --------------------------------------------------------------------------- synth, smoothing


def test_synth_negative_seed(tmp_path, capsys):
    refuses(tmp_path, capsys, ["synth", "--seed", "-1", "--out", str(tmp_path / "s.csv")],
            "--seed", ">= 0")


def test_synth_negative_strength_of_a_dissipative_effect(tmp_path, capsys):
    refuses(tmp_path, capsys, ["synth", "--effect", "seal_coulomb_friction", "--strength", "-1",
                               "--out", str(tmp_path / "s.csv")], "strength", ">= 0")


def test_smoothing_resistance_out_of_range(tmp_path, capsys):
    refuses(tmp_path, capsys, ["study", "smoothing", "--r-th-k-per-w", "1e6", "--out",
                               str(tmp_path / "sm")], "--r-th-k-per-w", "[0, 3] K/W")

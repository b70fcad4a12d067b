"""The oil-grade study (``oilgap study oil-grade``): the envelope, the mission and the grade.

:mod:`.study` runs it (``run``, ``OilGradeResult``, the mission), :mod:`.report` writes its
tables, figures and ``summary.md``, :mod:`.thermal` compares the recommendation with and
without heating. The study's names are re-exported here
(``from oilgap.studies.oil_grade import run``).
"""

from oilgap.studies.oil_grade.study import (
    ISO_GRADES,
    SEED_MISSION,
    OilGradeResult,
    oil_grade_study,
    parse_mission,
    read_mission_csv,
    run,
    summary_markdown,
    write_outputs,
)

__all__ = ["ISO_GRADES", "SEED_MISSION", "OilGradeResult", "oil_grade_study", "parse_mission",
           "read_mission_csv", "run", "summary_markdown", "write_outputs"]

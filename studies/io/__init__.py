"""oilgap.studies.io: the layer that writes files (the model and the optimizer write none).

:mod:`.files` (atomic writers, ``--out`` checks, no silent overwrite),
:mod:`.result_folder` (a result folder: its lock, the INCOMPLETE marker, ``--force``),
:mod:`.provenance` (the run as a record, :class:`~.provenance.RunRecord`, and
``provenance.json``) and :mod:`.case_write` (a case written as a TOML file).
"""

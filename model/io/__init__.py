"""oilgap.model.io: the readers and the case's TOML text; nothing here writes a file.

The case file read and validated (:mod:`.case_io`, its ``[bearing]`` table in
:mod:`.case_bearing`), the user's input files read or refused in one line
(:mod:`.inputs`), the physical limits of a case's geometry and motor (:mod:`.limits`),
rig tables read fast (:mod:`.tables`), the case as a TOML document (:mod:`.case_write`),
the one JSON/TOML text writer (:mod:`.serialize`), the defaults the tool filled in
(:mod:`.defaults`) and the layout of a command's text, the answer first (:mod:`.text`).
Writing files is the output layer's, :mod:`oilgap.studies.io`.
"""

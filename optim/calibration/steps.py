"""The log of the effect search: one :class:`SelectionStep` per decision.

The stepwise selection (:mod:`.selection`), the nonlinear refit (:mod:`.refit`) and
the plausibility check (:mod:`.search`) each record what they decided; the
estimator writes the log into ``loop.json`` as ``selection.steps``.
"""

from __future__ import annotations

from dataclasses import dataclass, fields


@dataclass(frozen=True, kw_only=True)
class SelectionStep:
    """One decision of the effect search.

    Only the fields of its kind are set; the others stay None and are left out
    of :meth:`to_dict`.

    Attributes
    ----------
    step : int or str
        The forward step (1, 2, ...) or the kind of decision: "prune",
        "structure", "nonlinear check", "nonlinear prune", "nonlinear add",
        "plausibility".
    best : str or None
        The effect (or pair, joined by " + ") a forward step tries.
    added, dropped : str or None
        The effect a nonlinear add adds, a prune drops.
    effects : list of str or None
        The effects the structure check judges together.
    rejected : list of str or str or None
        The effects a nonlinear check rejects, the effect a plausibility check rejects.
    heldout_rmse_W : float or None
        Held-out RMSE after a forward step [W].
    gain_pct : float or None
        Held-out gain of the step [%].
    explained_structure, explained_total : float or None
        Share of the held-out structure above the noise the step, and the set,
        explains [-].
    accepted : bool or None
        Whether a forward step or the structure check accepts.
    rejected_by : str or None
        The rule that rejects ("margin", "structure").
    reason : str or None
        Why a fit is implausible.
    """

    step: int | str
    best: str | None = None
    added: str | None = None
    dropped: str | None = None
    effects: list[str] | None = None
    rejected: list[str] | str | None = None
    heldout_rmse_W: float | None = None
    gain_pct: float | None = None
    explained_structure: float | None = None
    explained_total: float | None = None
    accepted: bool | None = None
    rejected_by: str | None = None
    reason: str | None = None

    def to_dict(self) -> dict:
        """JSON form: the fields that are set, in field order."""
        out = {}
        for f in fields(self):
            v = getattr(self, f.name)
            if v is not None:
                out[f.name] = list(v) if isinstance(v, tuple | list) else v
        return out

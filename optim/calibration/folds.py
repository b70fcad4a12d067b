"""Cross-validation folds of the loop: whole groups, at most :data:`MAX_FOLDS` folds.

Every held-out error, the effect selection and the jackknife intervals of the loop
leave out one *fold* at a time. A fold holds whole groups (the runs by default,
``cv_by`` otherwise), so a run is never split between training and test. The rule:

* ``g <= MAX_FOLDS`` groups: one fold per group, leave-one-group-out (the
  leave-one-run-out of a rig with a few long runs; the fold codes are the group
  codes).
* ``g > MAX_FOLDS`` groups: grouped ``MAX_FOLDS``-fold cross-validation [1]. The
  groups in their sorted order (the run names sorted, as ``run_code`` numbers them)
  are dealt round-robin: group of rank ``i`` goes to fold ``i mod MAX_FOLDS``. Folds
  differ by at most one group; runs named by oil or condition are spread over
  the folds rather than one condition in one fold.

The rule uses nothing but the group codes: no random draw, no dependence on the
core count, the same data give the same folds. The jackknife over the folds is then
the delete-a-group jackknife [2] with ``min(g, MAX_FOLDS)`` groups. The cost of the
loop's cross-validation grows with the number of folds (each fold re-evaluates the
forward model on all samples), so bounding it makes a campaign of a hundred short
runs cost what ten long runs of the same samples cost.

References
----------
.. [1] T. Hastie, R. Tibshirani, J. Friedman, *The Elements of Statistical
   Learning*, 2nd ed., Springer 2009, sec. 7.10 (K-fold cross-validation; K = 5 or
   10 recommended).
.. [2] B. Efron, C. Stein, "The jackknife estimate of variance", Ann. Stat.
   9:586-596, 1981 (delete-one-group jackknife); K. M. Wolter, *Introduction to
   Variance Estimation*, 2nd ed., Springer 2007, sec. 4.2 (delete-a-group jackknife
   over random groups).
"""

from __future__ import annotations

import numpy as np

from oilgap.model.errors import InputError
from oilgap.model.measured.data import Samples

MAX_FOLDS = 10
"""Most cross-validation folds; more groups than this are dealt into this many folds."""


def grouped_folds(groups: np.ndarray, k: int = MAX_FOLDS) -> np.ndarray:
    """Fold code of each sample: whole groups, leave-one-group-out up to ``k`` groups.

    Parameters
    ----------
    groups : array of int, shape (n,)
        Group code of each sample [-] (the run by default).
    k : int
        Most folds (>= 2).

    Returns
    -------
    array of int, shape (n,)
        The group codes themselves with ``k`` groups or fewer; otherwise
        ``rank mod k``, the rank of the sample's group among the sorted group
        codes (round-robin, deterministic).
    """
    groups = np.asarray(groups)
    if k < 2:
        raise InputError("max_folds", k, "at least 2 folds")
    uniq, rank = np.unique(groups, return_inverse=True)
    if len(uniq) <= k:
        return groups
    return (rank.ravel() % k).astype(np.int64)


def cv_folds(s: Samples, k: int = MAX_FOLDS) -> np.ndarray:
    """Fold code of each sample of ``s`` (:func:`grouped_folds` of its groups).

    Parameters
    ----------
    s : Samples
        Oil-run samples (their ``cv_group``, else the runs).
    k : int
        Most folds.

    Returns
    -------
    array of int
        Fold code [-]; the samples of one fold are left out together.
    """
    g = getattr(s, "cv_group", None)
    return grouped_folds(s.run_code if g is None else g, k)


def cv_scheme(s: Samples, k: int = MAX_FOLDS) -> dict:
    """The cross-validation scheme of ``s`` as recorded in ``loop.json`` and the report.

    Parameters
    ----------
    s : Samples
    k : int
        Most folds.

    Returns
    -------
    dict
        ``scheme`` ("leave-one-group-out" or "grouped k-fold"), ``by`` (the group
        column), ``groups`` and ``folds`` (counts [-]), ``max_folds``, ``rule``,
        ``jackknife`` and ``text`` (one sentence, e.g. "held-out error by grouped
        10-fold cross-validation over 80 oil runs").
    """
    g = getattr(s, "cv_group", None)
    n_groups = len(np.unique(s.run_code if g is None else g))
    by = getattr(s, "cv_by", "run") or "run"
    unit = "oil runs" if by == "run" else f"groups of {by}"
    if n_groups <= k:
        scheme, folds = "leave-one-group-out", n_groups
        name = "leave-one-run-out" if by == "run" else "leave-one-group-out"
        text = f"held-out error by {name} over {n_groups} {unit}"
        rule = f"one fold per group, {n_groups} groups <= {k}"
    else:
        scheme, folds = "grouped k-fold", k
        text = f"held-out error by grouped {k}-fold cross-validation over {n_groups} {unit}"
        rule = (f"{n_groups} > {k} groups: the groups in sorted order dealt round-robin, "
                f"group of rank i in fold i mod {k}; whole groups per fold")
    return {"scheme": scheme, "by": by, "groups": n_groups, "folds": folds, "max_folds": k,
            "rule": rule, "jackknife": f"delete-a-group jackknife over the {folds} folds",
            "text": text}

"""oilgap.optim: the clearance geometry as a CasADi/IPOPT design NLP, multi-objective
helpers, and the calibration engine of the measured-data loop.

* :mod:`oilgap.optim.design`: the design NLP (variables, parameters, objective,
  feasibility, results, problem);
* :mod:`oilgap.optim.scipy_reference`: the SciPy SLSQP cross-check of the NLP;
* :mod:`oilgap.optim.multiobjective`: non-dominated filter, 2-D hypervolume,
  epsilon spacing along a front;
* :mod:`oilgap.optim.calibration`: system identification of a rig's losses.
"""

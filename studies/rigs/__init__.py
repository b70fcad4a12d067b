"""Rigs simulated for the loop: :mod:`.synth` (the seed's viscous-power experiment,
``oilgap synth``), :mod:`.outside_rig` and :mod:`.outside_laws` (a rig outside the seed's
range, with laws the model does not hold)."""

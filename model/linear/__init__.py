"""The electric linear actuator in oil: laws (:mod:`oilgap.model.linear.laws`), the drive
(:mod:`.drive`) and its elements (:mod:`oilgap.model.linear.elements`);
docs/linear-joint.md."""

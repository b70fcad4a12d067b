"""The electric linear actuator in oil: laws (:mod:`.laws`), the drive (:mod:`.drive`) and
its elements (:mod:`.elements`); docs/linear-joint.md."""

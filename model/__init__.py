"""oilgap.model: the viscous-loss physics of oil-filled joint clearances."""

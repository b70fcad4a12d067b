"""The rig-test planning study (``oilgap plan``): candidate runs from the settings, the
optimal and the naive plan, their rehearsal with the loop, the result folder."""

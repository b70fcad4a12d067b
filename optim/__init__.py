"""oilgap.optim: the clearance geometry as a CasADi/IPOPT design NLP."""

# Demo robot: driver node and install rules.

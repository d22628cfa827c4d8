"""Independent references for the engine: high-precision solves."""

"""Synthesis of linkages by the time-ratio coefficient and by positions: to come."""

"""Cam mechanisms: to come; needs only the ground and the model."""

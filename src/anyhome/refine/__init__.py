"""Refine stage: geometric settling of placed objects (snaps, orientations, penetrations)."""

from anyhome.refine.refiner import refine_objects

__all__ = ["refine_objects"]

"""Planar texture coordinates in meters, per face.

Horizontal faces take ``(x, y)`` (``(x, -y)`` seen from below); upright faces take the
horizontal direction along the face and the height, ``(t . (x, y), z)`` with
``t = (-ny, nx)``, so a texture reads unmirrored and upright from in front of the face.
Coordinates are divided by the material's tile size, so one texture repeat covers
``tile_m`` meters whatever the mesh.
"""

from __future__ import annotations

import numpy as np
import trimesh

HORIZONTAL_NZ = 0.7
"""A face whose normal has |z| above this is mapped from (x, y)."""


def face_uv(corners: np.ndarray, normals: np.ndarray) -> np.ndarray:
    """Planar UVs in meters.

    Parameters
    ----------
    corners : (f, 3, 3) float, each face's vertices
    normals : (f, 3) float, unit face normals

    Returns
    -------
    (f, 3, 2) float
    """
    nz = normals[:, 2]
    horizontal = np.abs(nz) > HORIZONTAL_NZ
    t = np.column_stack([-normals[:, 1], normals[:, 0]])
    length = np.linalg.norm(t, axis=1, keepdims=True)
    t = np.where(length > 1e-9, t / np.maximum(length, 1e-9), np.array([1.0, 0.0]))
    along = np.einsum("fvk,fk->fv", corners[:, :, :2], t)
    flip = np.where(nz < 0, -1.0, 1.0)[:, None]
    u = np.where(horizontal[:, None], corners[:, :, 0], along)
    v = np.where(horizontal[:, None], corners[:, :, 1] * flip, corners[:, :, 2])
    return np.stack([u, v], axis=-1)


def face_normals(corners: np.ndarray) -> np.ndarray:
    """(f, 3) unit normals of (f, 3, 3) triangles (zero for degenerate ones)."""
    n = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    length = np.linalg.norm(n, axis=1, keepdims=True)
    return np.where(length > 1e-15, n / np.maximum(length, 1e-15), 0.0)


def with_planar_uv(vertices: np.ndarray, faces: np.ndarray, tile_m: float
                   ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Split a mesh into independent faces and give each corner planar UVs.

    Parameters
    ----------
    vertices : (v, 3) float
    faces : (f, 3) int
    tile_m : meters per texture repeat

    Returns
    -------
    vertices : (3f, 3) float
    faces : (f, 3) int
    uv : (3f, 2) float, meters / ``tile_m``
    """
    corners = np.asarray(vertices, dtype=float)[np.asarray(faces)]
    uv = face_uv(corners, face_normals(corners)) / float(tile_m)
    f = len(corners)
    return corners.reshape(-1, 3), np.arange(3 * f).reshape(f, 3), uv.reshape(-1, 2)


def textured_mesh(vertices: np.ndarray, faces: np.ndarray, material, tile_m: float) -> trimesh.Trimesh:
    """A mesh of the given faces with planar UVs (see module doc) and ``material``."""
    v, f, uv = with_planar_uv(vertices, faces, tile_m)
    out = trimesh.Trimesh(vertices=v, faces=f, process=False)
    out.visual = trimesh.visual.TextureVisuals(uv=uv, material=material)
    return out

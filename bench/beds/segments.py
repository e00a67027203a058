"""The distance between segments, many pairs at once."""

import numpy as np


def segment_distances(p0, p1, q0, q1):
    """The least distance between segment p0[i]-p1[i] and q0[i]-q1[i] for every row i (a
    segment may be a point): the closest points by clamping the parameters of the lines'
    closest points to [0, 1] (Ericson, Real-Time Collision Detection, 5.1.9)."""
    d1, d2, r = p1 - p0, q1 - q0, p0 - q0
    a = np.einsum("ij,ij->i", d1, d1)
    e = np.einsum("ij,ij->i", d2, d2)
    f = np.einsum("ij,ij->i", d2, r)
    c = np.einsum("ij,ij->i", d1, r)
    b = np.einsum("ij,ij->i", d1, d2)
    tiny = 1e-300
    denom = a * e - b * b
    # s on p's segment: from the lines' closest points, any s for parallel segments (0).
    s = np.where(denom > 1e-12 * np.maximum(a * e, tiny), np.clip((b * f - c * e) / np.maximum(denom, tiny), 0, 1), 0.0)
    s = np.where(a > tiny, s, 0.0)
    t = np.where(e > tiny, (b * s + f) / np.maximum(e, tiny), 0.0)
    # t outside [0, 1]: clamp it and recompute s for the clamped t.
    below, above = t < 0, t > 1
    t = np.clip(t, 0, 1)
    s = np.where(below & (a > tiny), np.clip(-c / np.maximum(a, tiny), 0, 1), s)
    s = np.where(above & (a > tiny), np.clip((b - c) / np.maximum(a, tiny), 0, 1), s)
    return np.linalg.norm((p0 + d1 * s[:, None]) - (q0 + d2 * t[:, None]), axis=1)

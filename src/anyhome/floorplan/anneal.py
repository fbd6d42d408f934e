"""Simulated annealing over slicing trees (postfix / Polish expressions, Wong-Liu).

A slicing tree is written as a postfix expression of room indices and cut operators
(``V``: cut across x, ``H``: cut across y). Cut positions follow the target areas, so
an expression fixes a whole layout; the annealer swaps rooms, flips cuts and rotates
operators to drive :func:`anyhome.floorplan.tune.layout_cost` (missing shared walls,
missing exterior walls, bad shapes) to zero.
"""

from __future__ import annotations

import math

import numpy as np

from anyhome.floorplan.options import FloorplanOptions
from anyhome.floorplan.slicing import Cut, Rect, tree_rects
from anyhome.floorplan.tune import TuneRooms, layout_cost

Token = int | str


def to_postfix(tree: Cut | int) -> list[Token]:
    if isinstance(tree, int):
        return [tree]
    return [*to_postfix(tree.low), *to_postfix(tree.high), "V" if tree.axis == 0 else "H"]


def from_postfix(expr: list[Token], rect: Rect, weights: np.ndarray | list[float]) -> Cut | int:
    """Tree of an expression, cuts placed by the leaves' ``weights`` (target cells)."""
    stack: list[tuple[Cut | int, float]] = []
    fractions: dict[int, float] = {}  # id(cut): the low side's share of its area
    for tok in expr:
        if isinstance(tok, str):
            (high, wh), (low, wl) = stack.pop(), stack.pop()
            cut = Cut(0 if tok == "V" else 1, 0, low, high)
            fractions[id(cut)] = wl / (wl + wh)
            stack.append((cut, wl + wh))
        else:
            stack.append((tok, float(weights[tok])))
    tree = stack[0][0]
    _place_cuts(tree, rect, fractions)
    return tree


def _place_cuts(tree: Cut | int, rect: Rect, fractions: dict[int, float]) -> None:
    """Turn each cut's area fraction (``fractions[id(cut)]``) into a cell coordinate."""
    if isinstance(tree, int):
        return
    lo, hi = (rect[0], rect[2]) if tree.axis == 0 else (rect[1], rect[3])
    tree.at = lo + int(round(fractions[id(tree)] * (hi - lo)))
    x0, y0, x1, y1 = rect
    if tree.axis == 0:
        low, high = (x0, y0, tree.at, y1), (tree.at, y0, x1, y1)
    else:
        low, high = (x0, y0, x1, tree.at), (x0, tree.at, x1, y1)
    _place_cuts(tree.low, low, fractions)
    _place_cuts(tree.high, high, fractions)


def anneal(tree: Cut | int, rect: Rect, rooms: TuneRooms, rng: np.random.Generator,
           options: FloorplanOptions | None = None) -> Cut | int:
    """Best tree found by annealing from ``tree`` (schedule: ``options``)."""
    opts = options or FloorplanOptions()
    expr = to_postfix(tree)
    if len(expr) < 3:
        return tree
    costs: dict[tuple[Token, ...], float] = {}  # the moves come back to the same expressions: two in three, measured

    def cost_of(e: list[Token]) -> float:
        key = tuple(e)
        if key not in costs:
            costs[key] = _cost(e, rect, rooms)
        return costs[key]

    cost = cost_of(expr)
    best, best_cost = list(expr), cost
    steps = opts.anneal_steps_per_room * (len(expr) + 1) // 2
    patience = max(1, math.ceil(opts.anneal_patience_frac * steps))
    found_at = 0  # the step that found the best tree so far
    for step in range(steps):
        if best_cost < 1e-9 or step - found_at > patience:
            break
        t0, t1 = opts.anneal_start_temperature, opts.anneal_end_temperature
        temp = t0 * (t1 / t0) ** (step / steps)
        cand = _move(expr, rng)
        if cand is None:
            continue
        c = cost_of(cand)
        if c <= cost or rng.random() < math.exp((cost - c) / temp):
            expr, cost = cand, c
            if c < best_cost:
                best, best_cost, found_at = list(cand), c, step
    return from_postfix(best, rect, rooms.lists.target_cells)


def _cost(expr: list[Token], rect: Rect, rooms: TuneRooms) -> float:
    return layout_cost(tree_rects(from_postfix(expr, rect, rooms.lists.target_cells), rect), rect, rooms)


def _move(expr: list[Token], rng: np.random.Generator) -> list[Token] | None:
    out = list(expr)
    kind = rng.integers(3)
    if kind == 0:  # swap two rooms
        leaves = [i for i, t in enumerate(out) if not isinstance(t, str)]
        a, b = rng.choice(len(leaves), size=2, replace=False).tolist()  # the draws of choice(leaves, ...), without the array
        i, j = leaves[a], leaves[b]
        out[i], out[j] = out[j], out[i]
    elif kind == 1:  # flip one cut
        ops = [i for i, t in enumerate(out) if isinstance(t, str)]
        i = ops[rng.integers(len(ops))]
        out[i] = "H" if out[i] == "V" else "V"
    else:  # swap an adjacent room and cut, if the expression stays valid
        i = int(rng.integers(len(out) - 1))
        if isinstance(out[i], str) == isinstance(out[i + 1], str):
            return None
        out[i], out[i + 1] = out[i + 1], out[i]
        if not _valid(out):
            return None
    return out


def _valid(expr: list[Token]) -> bool:
    depth = 0
    for tok in expr:
        depth += -1 if isinstance(tok, str) else 1
        if depth < 1:
            return False
    return depth == 1

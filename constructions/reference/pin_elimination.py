"""Invert the loop equations' Jacobian over a batch, the pins' translations eliminated first.

Over body coordinates most rows of ``Φ_q`` are a pin's: its two rows hold +1 and −1 in
the x and y columns of the two links it joins, at every position. Walking the pins out
from the frame (a spanning tree of the links they join), each link's translation is
fixed by the pin that reaches it, so those rows and columns form a block ``A`` of ±1,
triangular in the walk's order, the same at every position: its inverse is found once
and is exact (its entries are 0 and ±1). What is left is the Schur complement
``S = D − C A⁻¹ B`` over the links' angles and the translations no pin fixes, three
unknowns for a four-bar where ``Φ_q`` has nine, and

    Φ_q⁻¹ = [[A⁻¹ + Y S⁻¹ Z, −Y S⁻¹], [−S⁻¹ Z, S⁻¹]],   Y = A⁻¹ B,  Z = C A⁻¹.

This is Gaussian elimination with the ±1 entries as pivots: the multipliers are the
links' arms, summed along the walk, so nothing grows beyond the mechanism's size. A
batch of small matrices costs LAPACK a call each (a four-bar's 3600 inverses 9 × 9 took
5.5 ms); up to 3 × 3, ``S⁻¹`` is written out instead (its adjugate over its
determinant), so the whole batch is a few dozen array operations.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .batch_loops import BatchLoops, _Rows

__all__ = ["PinElimination", "Inverse"]


class PinElimination:
    """The pins' tree of a mechanism's loop equations, and Φ_q⁻¹ of a batch through it.

    ``rows`` and ``cols`` are the tree's pin rows and the translation columns they fix,
    in the walk's order (``A = Φ_q[rows, cols]``); ``rest_rows`` and ``rest_cols`` are
    the others, the Schur complement's.
    """

    def __init__(self, loops: BatchLoops):
        sy = loops.sy
        pins = [(row, item[1:]) for row, kind, item in loops.layout if kind is _Rows.PIN]
        rows: list[int] = []
        cols: list[int] = []
        reached, waiting = {1}, [1]
        left = [k for k in sy.moving]
        while left:
            if not waiting:       # no pin joins these links to the frame: the first is a root
                waiting.append(left.pop(0))
                reached.add(waiting[0])
            k = waiting.pop(0)
            for row, (i, j) in pins:
                new = j if i == k else i if j == k else None
                if new is None or new in reached:
                    continue
                reached.add(new)
                left.remove(new)
                waiting.append(new)
                rows += [row, row + 1]
                cols += [sy.col[new], sy.col[new] + 1]
        size = 3 * len(sy.moving)
        self.rows, self.cols = np.array(rows, dtype=int), np.array(cols, dtype=int)
        self.rest_rows = np.array([r for r in range(len(sy.is_len)) if r not in rows], dtype=int)
        self.rest_cols = np.array([c for c in range(size) if c not in cols], dtype=int)
        with np.errstate(all="ignore"):     # A is the pins' ±1 alone, at any position
            a = loops.jacobian(np.zeros((1, size)))[0][np.ix_(self.rows, self.cols)]
        self.a_inv = np.rint(np.linalg.inv(a)) if len(rows) else np.zeros((0, 0))
        # Φ_q's entries by block: B (tree rows, rest columns) and C (rest rows, tree columns)
        # enter only through A⁻¹ B and C A⁻¹, sums of a few entries each (A⁻¹ is 0 and ±1);
        # D is gathered; C's few entries (a closing pin's ±1, a slide's direction) multiply
        # A⁻¹ B one by one.
        place = {int(r): i for i, r in enumerate(self.rows)}
        take = {int(c): i for i, c in enumerate(self.cols)}
        rest = {int(r): i for i, r in enumerate(self.rest_rows)}
        free = {int(c): i for i, c in enumerate(self.rest_cols)}
        t, k = len(self.cols), len(self.rest_cols)
        y_terms, z_terms = [], []
        self._c: list[tuple[int, int, int]] = []
        for (row, col), e in loops.slots.items():
            if row in place and col in free:
                y_terms += [(i * k + free[col], e, a) for i, a in
                            enumerate(self.a_inv[:, place[row]].tolist())]
            elif row in rest and col in take:
                z_terms += [(rest[row] * t + j, e, a) for j, a in
                            enumerate(self.a_inv[take[col]].tolist())]
                self._c.append((rest[row], take[col], e))
        self._y, self._z = _Sums(t * k, y_terms), _Sums(k * t, z_terms)
        self._a = _Sums(t, [(i, j, a) for i, row in enumerate(self.a_inv.tolist())
                            for j, a in enumerate(row)])
        self._d = _Block(loops.slots, self.rest_rows, self.rest_cols)

    def invert(self, entries: np.ndarray, good: np.ndarray) -> Inverse:
        """``Φ_q⁻¹`` of each of a batch, from Φ_q's :meth:`~.BatchLoops.entries` (E, N), as
        its blocks; not inverted where not ``good``, nor where ``S`` is singular (see
        :attr:`Inverse.ok`)."""
        t, k, n = len(self.cols), len(self.rest_cols), entries.shape[1]
        y = self._y.of(entries).reshape(t, k, n)                             # A⁻¹ B
        s = self._d.of(entries)                                             # D − C A⁻¹ B
        for i, j, e in self._c:
            s[i] -= entries[e] * y[j]
        s_inv, ok = _small_inverse(s, good)
        w = np.einsum("rkn,kdn->rdn", s_inv, self._z.of(entries).reshape(k, t, n))  # S⁻¹ C A⁻¹
        return Inverse(self, y, w, s_inv, ok)


class _Sums:
    """A constant matrix of few nonzeros (``terms``: row, column, value) times a batch
    (columns, N): each row a sum of a few of the batch's rows. As a product it would be
    BLAS's, which splits one this size over threads, and those wait on a busy machine."""

    def __init__(self, rows: int, terms: list[tuple[int, int, float]]):
        self.rows = rows
        self.terms = [term for term in terms if term[2] != 0.0]

    def of(self, batch: np.ndarray) -> np.ndarray:
        """The product, (rows, N)."""
        out = np.zeros((self.rows, batch.shape[1]))
        for row, col, value in self.terms:
            if value == 1.0:
                out[row] += batch[col]
            elif value == -1.0:
                out[row] -= batch[col]
            else:
                out[row] += value * batch[col]
        return out


class _Block:
    """Where a block of Φ_q (its ``rows`` by its ``cols``) takes its entries from."""

    def __init__(self, slots: dict[tuple[int, int], int], rows, cols):
        self.shape = (len(rows), len(cols))
        at = [(i, j, slots[row, col]) for i, row in enumerate(rows)
              for j, col in enumerate(cols) if (row, col) in slots]
        self.i, self.j, self.slot = (np.array(x, dtype=int) for x in zip(*at)) if at else \
            (np.zeros(0, dtype=int),) * 3

    def of(self, entries: np.ndarray) -> np.ndarray:
        """The block at each of a batch: (rows, cols, N)."""
        out = np.zeros((*self.shape, entries.shape[1]))
        out[self.i, self.j] = entries[self.slot]
        return out


@dataclass(frozen=True)
class Inverse:
    """``Φ_q⁻¹`` of a batch as the blocks of its elimination, each (·, ·, N): ``y = A⁻¹ B``,
    ``w = S⁻¹ C A⁻¹`` and ``s_inv = S⁻¹``; ``ok`` where it inverted. Its rows of the pins'
    translations are ``[A⁻¹ + y w, −y S⁻¹]``, of the rest ``[−w, S⁻¹]`` (columns: the
    tree's pin rows, then the rest), never made whole: a 9 × 9 inverse of 3600 positions
    is 2.3 MB of fresh memory, which costs more to fault in than to fill."""

    tree: PinElimination
    y: np.ndarray
    w: np.ndarray
    s_inv: np.ndarray
    ok: np.ndarray

    def take(self, which: np.ndarray) -> Inverse:
        """The inverses of the positions ``which`` (a mask or indices) of the batch."""
        return Inverse(self.tree, self.y[..., which], self.w[..., which],
                       self.s_inv[..., which], self.ok[which])

    def column(self, row: int) -> np.ndarray:
        """Column ``row`` of each inverse (N, n): the rates the constraint ``row`` moves."""
        e = self.tree
        out = np.empty((self.y.shape[-1], len(e.rows) + len(e.rest_rows)))
        k = int(np.flatnonzero(e.rest_rows == row)[0])
        out[:, e.rest_cols] = self.s_inv[:, k].T
        out[:, e.cols] = -np.einsum("tkn,kn->nt", self.y, self.s_inv[:, k])
        return out

    def solve(self, rhs: np.ndarray) -> np.ndarray:
        """``Φ_q⁻¹ rhs`` of each row of ``rhs`` (N, n): ``x_U = S⁻¹ rhs_R − w rhs_P``,
        ``x_T = A⁻¹ rhs_P − y x_U``."""
        e = self.tree
        rp, rr = rhs[:, e.rows].T, rhs[:, e.rest_rows].T
        xu = np.einsum("kjn,jn->kn", self.s_inv, rr) - np.einsum("kjn,jn->kn", self.w, rp)
        out = np.empty(rhs.shape)
        out[:, e.rest_cols] = xu.T
        out[:, e.cols] = (e._a.of(rp) - np.einsum("tkn,kn->tn", self.y, xu)).T
        return out

    def norm2(self, rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
        """``‖diag(1/cols) Φ_q⁻¹ diag(1/rows)‖_F²`` of each (N,): the inverse's of the
        Jacobian whose rows are scaled by ``rows`` and columns by ``cols``. The rows of the
        pins' translations are taken one at a time: whole, they would be the largest
        arrays of a turn's solve."""
        e = self.tree
        ct, cu = 1.0 / cols[e.cols] ** 2, 1.0 / cols[e.rest_cols] ** 2
        rp, rr = 1.0 / rows[e.rows] ** 2, 1.0 / rows[e.rest_rows] ** 2
        total = (np.einsum("kdn,kdn,k,d->n", self.w, self.w, cu, rp)
                 + np.einsum("kjn,kjn,k,j->n", self.s_inv, self.s_inv, cu, rr))
        for t, weight in enumerate(ct.tolist()):
            tied = np.einsum("kn,kdn->dn", self.y[t], self.w)        # (A⁻¹ + y w)[t]
            tied += e.a_inv[t][:, None]
            free = np.einsum("kn,kjn->jn", self.y[t], self.s_inv)   # (y S⁻¹)[t]
            total += weight * (np.einsum("dn,dn,d->n", tied, tied, rp)
                               + np.einsum("jn,jn,j->n", free, free, rr))
        return total


def _small_inverse(s: np.ndarray, good: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``s⁻¹`` of each of a batch (k, k, N): by its adjugate up to 3 × 3, else by LAPACK;
    and which inverted (``good`` and not singular). The adjugate pivots on nothing, which
    costs nothing where it is used: a turn keeps the positions whose Jacobian has an
    rcond of 0.02 or more, and there it agrees with LAPACK to a few eps of the inverse
    (tests/test_pin_elimination.py)."""
    k = len(s)
    if k > 3:
        inv, ok = _lapack_inverse(s.transpose(2, 0, 1), good)
        return inv.transpose(1, 2, 0), ok
    if k == 1:
        det, adj = s[0, 0], np.ones_like(s)
    elif k == 2:
        det = s[0, 0] * s[1, 1] - s[0, 1] * s[1, 0]
        adj = np.stack([s[1, 1], -s[0, 1], -s[1, 0], s[0, 0]]).reshape(s.shape)
    else:                   # the columns of the inverse are the rows' cross products
        adj = np.empty_like(s)
        for col, (i, j) in enumerate(((1, 2), (2, 0), (0, 1))):
            a, b = s[i], s[j]
            adj[:, col] = a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], \
                a[0] * b[1] - a[1] * b[0]
        det = s[0, 0] * adj[0, 0] + s[0, 1] * adj[1, 0] + s[0, 2] * adj[2, 0]
    with np.errstate(divide="ignore", invalid="ignore"):     # singular: junk, never read
        return adj / det, good & np.isfinite(det) & (det != 0.0)


def _lapack_inverse(s: np.ndarray, good: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``s⁻¹`` of each of a batch by LAPACK (identity where not ``good`` or singular)."""
    if not good.all():
        s = np.where(good[:, None, None], s, np.eye(s.shape[1]))
    try:
        return np.linalg.inv(s), good.copy()
    except np.linalg.LinAlgError:
        inv, ok = np.empty_like(s), good.copy()
        for i in range(len(s)):
            try:
                inv[i] = np.linalg.inv(s[i])
            except np.linalg.LinAlgError:
                inv[i], ok[i] = np.eye(s.shape[1]), False
        return inv, ok

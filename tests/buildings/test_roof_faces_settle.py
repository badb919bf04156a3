"""Joint relabelling of arrangement cells left on jumps by the one-cell-at-a-time repair."""

from __future__ import annotations

import numpy as np

from workstation.buildings.roof_faces import MAX_LABELLINGS, _jumps, _repair, _settle_jumps


def _chain(n_free: int = 2):
    """Cells in a row, segments of 1 m: A (plane 0, 50 raster votes), ``n_free`` cells without
    votes, Z (plane 2, 50 votes). Along A's segment planes 0 and 1 meet, along Z's planes 1
    and 2, between the free cells only a plane with itself. Labelled 0 ... 0, 2 ... 2 the row
    jumps once in the middle, and every move of one cell only shifts the jump: all free cells
    on plane 1 is the one labelling without jumps."""
    n = n_free + 2
    c0, c1 = np.arange(n - 1), np.arange(1, n)
    a = np.column_stack([np.arange(n - 1.0), np.zeros(n - 1)])
    meet = np.repeat(np.eye(3, dtype=bool)[None], n - 1, axis=0)
    meet[0, 0, 1] = meet[0, 1, 0] = True
    meet[-1, 1, 2] = meet[-1, 2, 1] = True
    votes = np.zeros((n, 3), np.int64)
    votes[0, 0] = votes[-1, 2] = 50
    labels = np.where(np.arange(n) < n // 2, 0, 2)
    return labels, votes, (c0, c1, a, a + [0.0, 1.0]), meet


def test_joint_move_removes_a_jump_the_greedy_repair_cannot():
    labels, votes, seg, meet = _chain()
    stuck = _repair(labels, votes, seg, meet)
    assert _jumps(stuck, seg, meet).sum() == 1.0
    settled = _settle_jumps(stuck, votes, seg, meet)
    assert settled.tolist() == [0, 1, 1, 2]
    assert not _jumps(settled, seg, meet).any()


def test_labels_stay_when_no_labelling_is_free_of_jumps():
    labels, votes, seg, meet = _chain()
    meet[0, 0, 1] = meet[0, 1, 0] = False  # A's neighbour must now be plane 0, Z's plane 2
    assert np.array_equal(_settle_jumps(labels, votes, seg, meet), labels)


def test_too_many_labellings_are_not_tried():
    # every cell, A and Z too, on a jump: 3 planes ** (n_free + 2) labellings, just over the bound
    n_free = int(np.ceil(np.log(MAX_LABELLINGS + 1) / np.log(3))) - 2
    labels, votes, seg, meet = _chain(n_free)
    labels[1:-1] = (np.arange(n_free) + 1) % 2 * 2  # 2, 0, 2, ..., 0: every segment a jump
    assert (_jumps(labels, seg, meet) > 0).sum() == n_free + 1
    assert np.array_equal(_settle_jumps(labels, votes, seg, meet), labels)
    labels, votes, seg, meet = _chain(n_free - 1)
    labels[1:-1] = (np.arange(n_free - 1) + 1) % 2 * 2
    assert not _jumps(_settle_jumps(labels, votes, seg, meet), seg, meet).any()

"""Periodic orbits of the circular restricted three-body problem on float64 arrays, in the problem's own units:
equations of motion (cr3bp, compiled in _fast_cr3bp), first guesses (libration), differential correction
(shooting), continuation and stability (continuation) and the families (families).
"""

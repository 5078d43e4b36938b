"""Pulse programmers: what a specified shock pulse asks of a fixture, and the sizes of each concept
that can give it (``shockfem programmer``; closed forms in ``../shared/references/fixtures.md``)."""

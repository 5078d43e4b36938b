"""Outputs: the run directory, XDMF fields, time histories and plots."""

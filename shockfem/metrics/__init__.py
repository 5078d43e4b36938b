"""Shock-test metrics read from a run directory (or any acceleration history).

``signals``  uniform sampling; acceleration as interval means of a velocity history
``filters``  SAE J211 / ISO 6487 channel frequency class (CFC) filters
``srs``      shock response spectrum (Smallwood ramp-invariant recursive filter)
``pulse``    peak, duration, rise time, velocity change of the main pulse
``shapes``   ideal classical pulses, shape classification, MIL-STD-810 tolerance bands
``stages``   contact events and the per-stage table of a chain of bodies
``report``   all of the above for a run directory, into summary.json and PNG plots
"""

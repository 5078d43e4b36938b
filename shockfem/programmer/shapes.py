"""The pulse shapes a programmer may be sized for: the metrics' classical ones (``scene.specs.PULSE_SHAPES``)
and the rectangle.  A module of its own, importing nothing: the command line's parser offers them as the
choices of ``--shape`` without importing the sizing's libraries."""

SHAPES = ("half-sine", "terminal-peak sawtooth", "trapezoid", "rectangle")

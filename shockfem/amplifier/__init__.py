"""The velocity amplifier: a chain of ever smaller masses (an asymmetric Newton's cradle).

``gain``    closed-form rigid-body gains of the two machine architectures and the design tool
``rigid``   the event-driven rigid-body model of a chain (the ``rigid`` fidelity)
"""

"""Natural frequencies and mode shapes of a body (``shockfem modes``).

``eigen``   the generalised eigenproblem K x = omega^2 M x of one body, free-free or held by
            the scene's fixed, symmetry and velocity conditions, solved by SLEPc (shift-invert)
``labels``  what kind of mode each is: rigid, longitudinal, bending, radial, torsional
"""

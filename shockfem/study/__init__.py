"""Studies: sweeps of scenes at chosen fidelities, written up as a report (``shockfem study NAME``).

``report``     a Markdown report with tables and PNG figures in a results directory
``amplifier``  the white paper's task 3: the velocity amplifier
"""

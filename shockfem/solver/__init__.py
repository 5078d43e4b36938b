"""The explicit solver: compiled element kernels and the central-difference time loop."""

"""Contact: surfaces, the compiled penalty kernels, and contact pairs at run time."""

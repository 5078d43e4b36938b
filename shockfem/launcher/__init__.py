"""The gas-gun launcher (the white paper's task 4): a lumped model, structural sizing, design.

``gas``     ideal and Noble-Abel (covolume) gas, isentropic orifice flow (choked or not)
``gun``     reservoir -> valve -> barrel -> projectile, each loss switchable; ``fire`` integrates
``vessel``  ASME Section VIII Div. 1 UG-27 wall thickness and weight of barrel and tank
``design``  the lightest launcher for a required muzzle velocity (SLSQP), what binds, trade curves
``scene``   the [launcher] and [design] tables of a scene; ``output`` its files and console lines
"""

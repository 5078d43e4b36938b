"""Layout of the material parameter table the compiled kernels read: one row per scene material
(built by ``shockfem.model.materials.parameter_table``), one column per constant below."""

P_MODEL = 0            # 0 elastic, 1 J2 plasticity (solver/plasticity.py)
P_RHO = 1              # density [kg/m^3]
P_LAMBDA = 2           # Lame's first parameter [Pa]
P_MU = 3               # shear modulus [Pa]
P_WAVE_SPEED = 4       # dilatational wave speed [m/s]
P_BETA = 5             # stiffness-proportional damping [s]
P_KINEMATIC = 6        # kinematic hardening modulus H_k [Pa]
P_RATE_D = 7           # Cowper-Symonds D [1/s]; 0: rate independent
P_RATE_Q = 8           # Cowper-Symonds q [-]
P_RATE_FORM = 9        # 0: viscoplastic (LS-DYNA VP=1), 1: yield scaling by the total strain rate (VP=0)
P_CURVE_POINTS = 10    # points of the material's hardening curve (row of the curve table)
P_Q_QUADRATIC = 11     # bulk viscosity Q1 (LS-DYNA default 1.5)
P_Q_LINEAR = 12        # bulk viscosity Q2 (LS-DYNA default 0.06)
P_SLOT_WIDTH = 13      # total width of a slotted ring's axial slots [m] (axisymmetric split cone); 0: a full ring
NUM_PARAMS = 16

ELASTIC, PLASTIC = 0, 1

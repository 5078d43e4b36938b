"""The arrays the compiled material laws read and write, column by column.

* The parameter table ``params`` has one row per material row of a model (a scene material with
  a body's damping; built by ``shockfem.model.materials.parameter_table``) and the columns ``P_*``.
  ``P_LAW`` says which law of ``laws.LAWS`` the row follows.
* A curve table ``curves`` (rows, points, 2) holds each row's piecewise-linear curve: a J2 row's
  hardening (plastic strain, flow stress), a foam row's crush stress (volumetric strain, stress).
* The point state ``state`` (cells, points, ``STATE_SIZE``) holds what a law carries from step to
  step, columns ``S_*``.  A model in which no law needs state passes a (1, 1, STATE_SIZE) stub.
"""

# law ids (``laws.LAWS`` names them)
ELASTIC, J2, FOAM, RUBBER = 0, 1, 2, 3

# parameter columns
P_LAW = 0              # the row's law: ELASTIC, J2, FOAM or RUBBER
P_RHO = 1              # density [kg/m^3]
P_LAMBDA = 2           # Lame's first parameter [Pa]
P_MU = 3               # shear modulus [Pa]
P_WAVE_SPEED = 4       # dilatational wave speed [m/s]
P_BETA = 5             # stiffness-proportional damping [s]
P_KINEMATIC = 6        # kinematic hardening modulus H_k [Pa] (J2)
P_RATE_D = 7           # Cowper-Symonds D [1/s]; 0: rate independent (J2, foam)
P_RATE_Q = 8           # Cowper-Symonds q [-] (J2, foam)
P_RATE_FORM = 9        # 0: viscoplastic (LS-DYNA VP=1), 1: yield scaling by the total strain rate (VP=0)
P_CURVE_POINTS = 10    # points of the row's curve (J2, foam)
P_Q_QUADRATIC = 11     # bulk viscosity Q1 (LS-DYNA default 1.5)
P_Q_LINEAR = 12        # bulk viscosity Q2 (LS-DYNA default 0.06)
P_SLOT_WIDTH = 13      # total width of a slotted ring's axial slots [m] (axisymmetric split cone); 0: a full ring
P_TENSION_CUTOFF = 14  # largest principal tensile stress [Pa] (foam)
P_C01 = 15             # Mooney-Rivlin C01 [Pa] (rubber; C10 = mu / 2 - C01)
NUM_PARAMS = 16

# rate forms of the Cowper-Symonds factor (P_RATE_FORM)
VISCOPLASTIC, YIELD_SCALING = 0, 1

# state columns
S_EPS = 0              # equivalent plastic strain [-] (J2; foam: sum of sqrt(2/3 d eps_p : d eps_p))
S_RATE = 1             # equivalent plastic strain rate of the last step [1/s]
S_BACK = 2             # back stress, columns 2..7 in the stress order (11 22 33 23 13 12) [Pa]
S_SLOT = 8             # how much of a slotted ring's slot width has closed [m]
S_LOG_VOLUME = 9       # ln(V / V0), the integral of tr(d) dt (foam)
S_DEFORMATION = 10     # F - I, the deformation gradient less the identity, row-major, columns 10..18 (rubber)
STATE_SIZE = 19

# The constants of Radau IIA of order 5 as Hairer & Wanner's code RADAU5 uses them (Solving
# Ordinary Differential Equations II, sec. IV.8; subroutine RADCOR), to 20 digits, for the loop
# in loops.pxi and for driver.radau_constants (tests/test_radau.py checks them against the
# Butcher tableau): the nodes RA_C1, RA_C2 (and 1) and the reciprocals RA_IC* the loop multiplies
# by (a division stalls it); the eigenvalues of A^-1, gamma and
# alpha +- i beta; T, whose columns transform A^-1 to diag(gamma, [[alpha, -beta], [beta,
# alpha]]) (T32 = 1, T33 = 0), and its inverse TI; the error estimator's weights RA_DD; the
# Newton iteration's sweeps, safety factor, step-ratio limits and the window of step ratios
# within which a step keeps its LU factors (RA_QUOT1, RA_QUOT2).
cdef extern from *:
    """
    #define RA_C1 0.15505102572168219018
    #define RA_C2 0.64494897427831780982
    #define RA_C1M1 (RA_C1 - 1.0)
    #define RA_C2M1 (RA_C2 - 1.0)
    #define RA_C1MC2 (RA_C1 - RA_C2)
    #define RA_IC1 (1.0 / RA_C1)
    #define RA_IC2 (1.0 / RA_C2)
    #define RA_IC1M1 (1.0 / RA_C1M1)
    #define RA_IC2M1 (1.0 / RA_C2M1)
    #define RA_IC1MC2 (1.0 / RA_C1MC2)
    #define RA_GAMMA 3.6378342527444957322
    #define RA_ALPHA 2.6810828736277521339
    #define RA_BETA 3.0504301992474105694
    #define RA_DD1 (-10.048809399827415562)
    #define RA_DD2 1.3821427331607488958
    #define RA_DD3 (-0.33333333333333333333)
    #define RA_T11 9.1232394870892942792e-02
    #define RA_T12 (-0.14125529502095420843)
    #define RA_T13 (-3.0029194105147424492e-02)
    #define RA_T21 0.24171793270710701896
    #define RA_T22 0.20412935229379993199
    #define RA_T23 0.38294211275726193779
    #define RA_T31 0.96604818261509293619
    #define RA_TI11 4.3255798900631553510
    #define RA_TI12 0.33919925181580986954
    #define RA_TI13 0.54177053993587487119
    #define RA_TI21 (-4.1787185915519047273)
    #define RA_TI22 (-0.32768282076106238708)
    #define RA_TI23 0.47662355450055045196
    #define RA_TI31 (-0.50287263494578687595)
    #define RA_TI32 2.5719269498556054292
    #define RA_TI33 (-0.59603920482822492497)
    #define RA_NIT 7
    #define RA_SAFE 0.9
    #define RA_FACL 5.0
    #define RA_FACR 0.125
    #define RA_QUOT1 1.0
    #define RA_QUOT2 1.2
    """
    const double RA_C1
    const double RA_C2
    const double RA_C1M1
    const double RA_C2M1
    const double RA_C1MC2
    const double RA_IC1
    const double RA_IC2
    const double RA_IC1M1
    const double RA_IC2M1
    const double RA_IC1MC2
    const double RA_GAMMA
    const double RA_ALPHA
    const double RA_BETA
    const double RA_DD1
    const double RA_DD2
    const double RA_DD3
    const double RA_T11
    const double RA_T12
    const double RA_T13
    const double RA_T21
    const double RA_T22
    const double RA_T23
    const double RA_T31
    const double RA_TI11
    const double RA_TI12
    const double RA_TI13
    const double RA_TI21
    const double RA_TI22
    const double RA_TI23
    const double RA_TI31
    const double RA_TI32
    const double RA_TI33
    const int RA_NIT
    const double RA_SAFE
    const double RA_FACL
    const double RA_FACR
    const double RA_QUOT1
    const double RA_QUOT2

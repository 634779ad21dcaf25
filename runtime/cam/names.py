"""What the command line offers of the cam's followers and materials, free of NumPy so that
`camdyn --help` stays light."""

KINDS = ("translating-roller", "oscillating-roller", "translating-flat", "oscillating-flat")
"""The followers (runtime/cam/follower.py), as ``camdyn profile --follower`` names them."""

MATERIALS = {
    "steel": (207e9, 0.292),
    "stainless-steel": (190e9, 0.305),
    "cast-iron": (100e9, 0.211),
    "phosphor-bronze": (111e9, 0.349),
    "brass": (106e9, 0.324),
    "aluminium": (71.7e9, 0.333),
}
"""name -> (E in Pa, nu): typical handbook values (Shigley's Mechanical Engineering Design,
table A-5), for the contact stress (runtime/cam/stress.py)."""

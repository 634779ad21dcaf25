"""What can run and how it is prepared: a built-in model or a model file, the CAMSHAFT-1
study, a DYNACAM scene, the Rayleigh-beam follower.  Each is a Target with its parameters and
their ranges, its headline figures, how to prepare and tighten a run and what window its
figures need; one resolve() turns a command-line argument or a scene file into one."""

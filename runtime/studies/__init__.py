"""Many runs of one target: sweeps over a grid, work-precision studies with SciPy's
integrators beside camdyn's, stability maps, the least model of a scene, and the CAMSHAFT-1
study of thesis ch. 4."""

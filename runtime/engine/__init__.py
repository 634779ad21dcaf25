"""The compiled floor under the generated models: the C interface every generated model
implements (abi.pxd), the integration loops compiled into each of them (loops.pxi), the small
dense linear algebra they use (linalg.pxd), the driver that calls them (driver) and the
compiled figure finder (finder).  Nothing here imports a Python module of camdyn."""

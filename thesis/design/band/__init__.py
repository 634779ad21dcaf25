"""A machine over its speed band: from a designer's numbers (a stroke in mm, the four cam
angles, the follower train's mass and stiffness, a band of speeds in rpm) to the law, the
spring and the cam that hold from the lowest speed to the highest (`camdyn design MACHINE.toml
--laws all`).

    spec      the machine, described once: a scene kind (TOML) and the same as options
    units     one rule for units: a number is SI (angles in degrees), a string carries its own
"""

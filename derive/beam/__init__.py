"""Translating roller follower with a flexible (Rayleigh-beam) rod in a grooved disk cam, after
*Transverse Vibration Analysis of a Translating Roller-Follower Cam Using Cycloidal Profile
for RDFD Motion* (cited as "the paper")."""

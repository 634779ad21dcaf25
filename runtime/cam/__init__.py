"""The cam as a part: the follower's motion over a turn (rise, dwell, return, dwell) and the
disk cam's pitch curve and profile, with pressure angle and curvature."""

"""The house's infrastructure, shared by every subject and the command line: the unit boundary (units), the
input rules (inputs), the catalogue of bodies (constants), display units and digits (display), quantity tables
(tables), atomic file output (io), facts about this installation (system) and the frame every picture shares
(frame). Private: users reach what they need through `orbits` and its subject packages.
"""

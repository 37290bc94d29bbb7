"""Getting from one orbit to another on float64 arrays (SI, radians): impulsive transfers (impulsive), the rocket
equation (rocket), gravity assists (assist) and Lambert's problem (lambert, compiled in _fast_lambert).
"""

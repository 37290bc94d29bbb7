"""Force models and events on float64 arrays (SI): the accelerations a perturbed orbit integrates and the
located events of its dense output. The home of the subject in the core; its modules land with the subject.
"""

"""SGP4 and SDP4 on float64 arrays (km, minutes as the model defines them), and the frames of their states. The
home of the subject in the core; its modules land with the subject.
"""

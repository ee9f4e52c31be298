"""ellipse_collision for Python.

ellipse_collision.core: the C++ core's ellipse tests (overlap, contact_scale, distance,
first_contact, minimum_area_ellipse, check_scene) and their batch forms on numpy arrays; see
doc/python.md. ellipse_collision.msg and ellipse_collision.srv: the node's messages and services.
"""

# The Python package ellipse_collision (python/ellipse_collision/), installed by
# catkin_python_setup(): its compiled module `core` is built by CMake (cmake/python.cmake), the
# messages by genpy.
from setuptools import setup

from catkin_pkg.python_setup import generate_distutils_setup

setup(**generate_distutils_setup(packages=["ellipse_collision"], package_dir={"": "python"}))

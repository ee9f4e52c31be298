#!/usr/bin/env bash
# Installs everything needed to build, test and run ellipse_collision from Debian 12's own
# packages (ROS 1 included: no ROS apt repository, nothing built from source but this package).
# Runs as root, or through sudo otherwise. Does nothing, quickly, when all is already installed.
set -euo pipefail

# ------------------------------------------------------------------------------------------------
# THE dependency list: every Debian package the build, the tests and the demo need.
# Add new dependencies here (and to package.xml when they are ROS packages).
DEBIAN_PACKAGES=(
  # toolchain
  g++
  cmake
  make
  python3
  # ROS 1 build system and client library
  catkin
  ros-core-dev
  libroscpp-dev
  ros-message-generation
  # ROS messages and tf
  libstd-msgs-dev
  libgeometry-msgs-dev
  libvisualization-msgs-dev
  libdiagnostic-msgs-dev
  libtf2-ros-dev
  libtf2-eigen-dev
  libtf2-geometry-msgs-dev
  # The Python side of every message package the package's messages, services and topics use
  # (rosservice, rostopic and rospy clients load them); test/python/check_message_types.py fails
  # when one is missing, so this list cannot drift from msg/, srv/ and the node's topics.
  python3-std-msgs
  python3-geometry-msgs
  python3-visualization-msgs
  python3-diagnostic-msgs
  python3-sensor-msgs
  python3-nav-msgs
  python3-std-srvs
  python3-tf2-msgs
  python3-rosgraph-msgs
  python3-roslib
  python3-rospy
  python3-rosmsg
  # ROS command-line tools (rosrun, roslaunch, rostest and the introspection tools tests use)
  rosbash
  python3-roslaunch
  python3-rostest
  python3-rosservice
  python3-rostopic
  python3-rosnode
  python3-rosparam
  librostest-dev
  # demo: robot model, tf from joint states, rviz headless and its screenshot
  libstd-srvs-dev
  libsensor-msgs-dev
  libnav-msgs-dev
  ros-robot-state-publisher
  rviz
  xvfb
  xauth
  imagemagick
  libx11-dev
  # robot model in: URDF parsing (urdf::Model), meshes through assimp and package:// / file://
  # URIs through resource_retriever (fit_link_ellipses, ~links_from_urdf)
  liburdf-dev
  libassimp-dev
  # assimp's CMake targets link /usr/lib/x86_64-linux-gnu/libz.so, which libassimp-dev does not pull
  # in (found by scripts/fresh_machine.sh: "No rule to make target .../libz.so")
  zlib1g-dev
  libresource-retriever-dev
  # incident bags: written by the node (rosbag::Bag), read by incident_report
  librosbag-dev
  python3-rosbag
  python3-matplotlib
  # nodelets (launch/scan_pipeline_nodelets.launch): the Nodelet base class and its library, the
  # load/list services (C++ and, for rosservice, Python), the plugin export macro, and the
  # `nodelet` executable (manager and loader)
  libnodeletlib-dev
  libnodelet-dev
  pluginlib-dev
  libnodeletlib-tools
  python3-nodelet
  # parameters changed while the node runs: the C++ server (cfg/*.cfg, generated at build time by
  # its Python generator) and the Python client that rqt_reconfigure and the rostest use
  libdynamic-reconfigure-config-init-mutex-dev
  python3-dynamic-reconfigure
  # fuzzing: clang with libFuzzer and the sanitizer runtimes
  clang
  libclang-rt-14-dev
  # Python bindings of the core (cmake/python.cmake, doc/python.md): pybind11 and the Python
  # headers it compiles against (pybind11-dev does not pull them in), setuptools for setup.py;
  # numpy for the batch functions, mpmath for the tests' 40-digit oracle, shapely for the
  # benchmark's polygon comparison
  pybind11-dev
  python3-pybind11
  python3-dev
  python3-setuptools
  python3-numpy
  python3-mpmath
  python3-shapely
  # libraries
  libeigen3-dev
  libgtest-dev
  libbenchmark-dev
  libfcl-dev
)
# ------------------------------------------------------------------------------------------------

# dpkg-query exits non-zero for packages it has never heard of; their lines are simply missing.
installed="$(dpkg-query -W -f='${Package} ${db:Status-Status}\n' "${DEBIAN_PACKAGES[@]}" 2>/dev/null \
  | awk '$2 == "installed" { print $1 }' || true)"
missing=()
for package in "${DEBIAN_PACKAGES[@]}"; do
  if ! grep -qx -- "${package}" <<<"${installed}"; then
    missing+=("${package}")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "setup.sh: all ${#DEBIAN_PACKAGES[@]} Debian packages are installed"
  exit 0
fi

if ((EUID == 0)); then
  as_root=()
elif command -v sudo >/dev/null; then
  as_root=(sudo)
else
  echo "setup.sh: must run as root (or with sudo available) to install: ${missing[*]}" >&2
  exit 1
fi

echo "setup.sh: installing ${#missing[@]} Debian packages: ${missing[*]}"
# A fresh machine has empty package lists, so always update before installing.
"${as_root[@]}" apt-get update
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y --no-install-recommends "${missing[@]}"

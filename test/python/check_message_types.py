#!/usr/bin/env python3
"""Every message and service type a user of ellipse_collision meets must load in Debian's Python.

rosservice, rostopic and rospy clients load message classes from Python modules, which Debian
ships apart from the C++ headers (libgeometry-msgs-dev vs python3-geometry-msgs). This test
collects the types from the package itself, so it cannot drift from what the package uses:
  - the package's own messages and services (msg/*.msg, srv/*.srv),
  - every type their fields name (std_msgs/Header, geometry_msgs/Point, ...),
  - every type the C++ code advertises, subscribes to or calls (advertise<T>, subscribe<T>,
    serviceClient<T>), and the types tf, rosout and simulated time use beneath every node.
Each type is loaded with roslib.message.get_message_class / get_service_class, as rostopic and
rosservice do; one JUnit test case per type.

usage: check_message_types.py PACKAGE_DIR [--junit FILE]
"""
import argparse
import os
import re
import sys
from xml.sax.saxutils import escape, quoteattr

PACKAGE = "ellipse_collision"
# Beneath every roscpp node: tf2_ros's listener (/tf, /tf_static), rosout, and /clock under
# use_sim_time. Users echo these when they debug the node.
IMPLICIT_MESSAGES = ["tf2_msgs/TFMessage", "rosgraph_msgs/Log", "rosgraph_msgs/Clock"]
BUILTIN = {"bool", "int8", "uint8", "int16", "uint16", "int32", "uint32", "int64", "uint64",
           "float32", "float64", "string", "time", "duration", "byte", "char", "Header"}
CPP_USE = re.compile(
    r"\b(advertise|subscribe|serviceClient|advertiseService)<\s*([A-Za-z_][\w:]*)\s*>")


def field_types(path, package):
    """Package-qualified message types named by the fields of a .msg or .srv file."""
    types = set()
    with open(path) as spec:
        for line in spec:
            line = line.split("#", 1)[0].strip()
            if not line or line == "---" or "=" in line.split()[-1]:
                continue
            base = re.sub(r"\[\d*\]$", "", line.split()[0])
            if base == "Header":
                types.add("std_msgs/Header")
            elif base not in BUILTIN:
                types.add(base if "/" in base else package + "/" + base)
    return types


def cpp_types(package_dir):
    """(messages, services) the C++ sources use, as package/Type."""
    messages, services = set(), set()
    for folder in ("src", "include", "test", "bench"):
        for directory, _, files in os.walk(os.path.join(package_dir, folder)):
            for name in files:
                if not name.endswith((".cpp", ".h")):
                    continue
                with open(os.path.join(directory, name), errors="replace") as source:
                    for verb, cpp_type in CPP_USE.findall(source.read()):
                        parts = cpp_type.split("::")
                        if len(parts) == 1:
                            if not re.match(r"^[A-Z]\w+$", parts[0]) or parts[0] in ("M", "T"):
                                continue  # a template parameter, not a message type
                            parts = [PACKAGE] + parts
                        ros_type = parts[-2] + "/" + parts[-1]
                        is_service = verb in ("serviceClient", "advertiseService")
                        (services if is_service else messages).add(ros_type)
    return messages, services


def collect(package_dir):
    messages, services = cpp_types(package_dir)
    messages.update(IMPLICIT_MESSAGES)
    for folder, kind in (("msg", messages), ("srv", services)):
        directory = os.path.join(package_dir, folder)
        for name in sorted(os.listdir(directory)) if os.path.isdir(directory) else []:
            stem, ext = os.path.splitext(name)
            if ext not in (".msg", ".srv"):
                continue
            kind.add(PACKAGE + "/" + stem)
            messages.update(field_types(os.path.join(directory, name), PACKAGE))
    return sorted(messages), sorted(services)


def load(kind, ros_type):
    """None if the class loads, else why not."""
    import roslib.message
    try:
        getter = (roslib.message.get_message_class if kind == "msg"
                  else roslib.message.get_service_class)
        loaded = getter(ros_type, reload_on_error=True)
    except Exception as error:  # what rostopic would print instead of the topic
        return "%s: %s" % (type(error).__name__, error)
    return None if loaded is not None else "Unable to load type [%s]" % ros_type


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("package_dir")
    parser.add_argument("--junit")
    args = parser.parse_args()
    messages, services = collect(args.package_dir)
    cases = [("msg", t) for t in messages] + [("srv", t) for t in services]
    try:
        import roslib.message  # noqa: F401
        problems = {case: load(*case) for case in cases}
    except ImportError as error:
        problems = {case: "python3-roslib missing: %s" % error for case in cases}
    failed = sum(1 for problem in problems.values() if problem)
    for (kind, ros_type), problem in sorted(problems.items()):
        print("%-6s %-4s %s%s" % ("FAILED" if problem else "ok", kind, ros_type,
                                  ": " + problem if problem else ""))
    if args.junit:
        os.makedirs(os.path.dirname(os.path.abspath(args.junit)), exist_ok=True)
        with open(args.junit, "w") as out:
            out.write('<?xml version="1.0" encoding="UTF-8"?>\n')
            out.write('<testsuite name="message_types" tests="%d" failures="%d" errors="0">\n'
                      % (len(cases), failed))
            for (kind, ros_type), problem in sorted(problems.items()):
                out.write('  <testcase classname="message_types.%s" name=%s>' % (kind, quoteattr(ros_type)))
                if problem:
                    out.write('<failure message=%s>%s</failure>' % (quoteattr(problem), escape(problem)))
                out.write("</testcase>\n")
            out.write("</testsuite>\n")
    print("%d types load, %d do not" % (len(cases) - failed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

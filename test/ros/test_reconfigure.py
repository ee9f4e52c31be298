#!/usr/bin/env python3
"""rostest: dynamic_reconfigure of the collision node, as a user drives it.

The scene, by hand: `body` (circle r 0.5 at x 0) and `crate` (circle r 0.5 at x 1.2) are 0.2 m
apart. A warning_distance above 0.2 makes them a warning pair; a padding p grows both radii, so
above 0.1 they overlap.
"""
import threading
import time
import unittest

import rospy
import rostest
from dynamic_reconfigure.client import Client
from geometry_msgs.msg import Twist
from rosgraph_msgs.msg import Log

from ellipse_collision.msg import CollisionState, GateState
from ellipse_collision.srv import CheckCollisions

NODE = "/ellipse_collision"


class ReconfigureTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_reconfigure")
        cls.log = []
        cls.lock = threading.Lock()
        rospy.Subscriber("/rosout", Log, cls.on_log)
        rospy.wait_for_service(NODE + "/check_collisions", timeout=30)
        cls.check = rospy.ServiceProxy(NODE + "/check_collisions", CheckCollisions)
        cls.client = Client(NODE, timeout=30)
        cls.gate = Client(NODE + "/gate", timeout=30)

    @classmethod
    def on_log(cls, msg):
        if msg.name == NODE:
            with cls.lock:
                cls.log.append(msg)

    def errors_about(self, text, since):
        deadline = time.time() + 5.0
        while time.time() < deadline:
            with self.lock:
                found = [m.msg for m in self.log
                         if m.level == Log.ERROR and text in m.msg and m.header.stamp.to_sec() >= since]
            if found:
                return found
            time.sleep(0.1)
        return []

    def test_1_groups_and_documented_parameters(self):
        # rqt_reconfigure shows the groups and each parameter's description with its unit.
        groups = self.client.get_group_descriptions(timeout=10)
        names = {group["name"] for group in groups["groups"].values()}
        self.assertTrue({"check", "time"} <= names, names)
        params = {p["name"]: p for p in self.client.get_parameter_descriptions(timeout=10)}
        for name in ("rate", "padding", "warning_distance", "max_transform_age",
                     "obstacle_timeout", "prediction_horizon"):
            self.assertIn(name, params)
            self.assertIn("[", params[name]["description"], name)  # a unit
        gate = {p["name"] for p in self.gate.get_parameter_descriptions(timeout=10)}
        self.assertTrue({"enabled", "horizon", "stop_time", "on_incomplete"} <= gate, gate)
        # The servers start from the node's parameters.
        config = self.client.get_configuration(timeout=10)
        self.assertEqual(config["rate"], 10.0)
        self.assertEqual(config["padding"], 0.0)

    def test_2_warning_distance_and_padding_change_the_answer(self):
        self.assertEqual(len(self.check().warnings), 0)
        config = self.client.update_configuration({"warning_distance": 0.3})
        self.assertEqual(config["warning_distance"], 0.3)
        answer = self.check()
        self.assertTrue(answer.success, answer.message)
        self.assertEqual([(w.name_a, w.name_b) for w in answer.warnings], [("body", "crate")])
        self.assertAlmostEqual(answer.warnings[0].distance, 0.2, places=9)
        config = self.client.update_configuration({"padding": 0.15})
        self.assertEqual(config["padding"], 0.15)
        answer = self.check()
        self.assertTrue(answer.in_collision)
        self.assertEqual([(c.name_a, c.name_b) for c in answer.collisions], [("body", "crate")])
        self.client.update_configuration({"padding": 0.0})
        self.assertFalse(self.check().in_collision)

    def test_3_refused_values_are_named_and_the_kept_ones_reported(self):
        for key, value, kept in (("padding", -1.0, 0.0), ("rate", 5000.0, 10.0),
                                 ("max_transform_age", 4000.0, 0.5),
                                 ("warning_distance", float("nan"), None)):
            before = self.client.get_configuration(timeout=10)
            since = rospy.get_time()
            config = self.client.update_configuration({key: value})
            expected = before[key] if kept is None else kept
            self.assertEqual(config[key], expected, key)
            errors = self.errors_about("parameter ~" + key, since)
            self.assertTrue(errors, "no error naming ~%s" % key)
            self.assertIn("nothing changed", errors[0])
            self.assertIn("kept:", errors[0])
        # The answer is what it was.
        self.assertTrue(self.check().success)

    def test_4_rate_changes_the_periodic_check(self):
        def count(seconds):
            stamps = []
            sub = rospy.Subscriber(NODE + "/collisions", CollisionState,
                                   lambda m: stamps.append(m.header.stamp.to_sec()))
            time.sleep(seconds)
            sub.unregister()
            return len(stamps)
        self.client.update_configuration({"rate": 2.0})
        time.sleep(1.0)
        slow = count(3.0)
        self.client.update_configuration({"rate": 20.0})
        time.sleep(0.5)
        fast = count(3.0)
        self.client.update_configuration({"rate": 10.0})
        self.assertLessEqual(slow, 9, "rate 2 Hz for 3 s")
        self.assertGreaterEqual(fast, 40, "rate 20 Hz for 3 s")

    def test_5_gate_reconfigured_at_run_time(self):
        states = []
        rospy.Subscriber(NODE + "/gate_state", GateState, states.append)
        command = rospy.Publisher(NODE + "/cmd_vel_in", Twist, queue_size=1)
        time.sleep(1.0)
        twist = Twist()
        twist.linear.x = 0.1

        def last_action():
            del states[:]
            command.publish(twist)
            deadline = time.time() + 5.0
            while not states and time.time() < deadline:
                time.sleep(0.05)
            return states[-1].action if states else None
        self.assertEqual(last_action(), "DISABLED")
        config = self.gate.update_configuration({"enabled": True})
        self.assertTrue(config["enabled"])
        # body moves towards crate, 0.2 m away at 0.1 m/s: contact in 2 s, beyond the 1.5 s rule.
        self.assertEqual(last_action(), "PASS")
        self.gate.update_configuration({"time_before_collision": 2.5})
        self.assertEqual(last_action(), "SLOW")
        # stop_time above time_before_collision breaks the gate's own rule: refused, kept.
        since = rospy.get_time()
        config = self.gate.update_configuration({"stop_time": 3.0})
        self.assertEqual(config["stop_time"], 0.3)
        self.assertTrue(self.errors_about("gate/stop_time", since))
        config = self.gate.update_configuration({"on_incomplete": "maybe"})
        self.assertEqual(config["on_incomplete"], "stop")
        self.gate.update_configuration({"enabled": False, "time_before_collision": 1.5})
        self.assertEqual(last_action(), "DISABLED")


if __name__ == "__main__":
    rostest.rosrun("ellipse_collision", "reconfigure", ReconfigureTest)

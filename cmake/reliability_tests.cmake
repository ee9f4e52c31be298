# Hostile-input rostest battery, bad-configuration start-up tests, load test.

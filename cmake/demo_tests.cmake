# Demo test: headless rviz screenshot check.

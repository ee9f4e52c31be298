# Collision benchmarks: pair tests, scene checks, service round trip.

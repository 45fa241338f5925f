"""The crank search's tests: the ``heavy`` mark (a whole search of an in-line 13 or more, or a
cluster of several processes: seconds each; ``pytest -m "not heavy"`` leaves them out)."""


def pytest_configure(config):
    config.addinivalue_line(
        "markers", "heavy: a search of seconds (an in-line 13, or a cluster of processes)"
    )

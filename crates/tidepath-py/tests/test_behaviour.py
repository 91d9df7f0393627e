"""What a Python user expects of a long run: the GIL released, Ctrl-C honoured."""

import os
import signal
import threading
import time

import numpy as np
import pytest

from tidepath import Scenario


def test_a_python_thread_runs_while_a_plan_runs():
    s = Scenario.builtin("demo")
    ticks = []
    done = threading.Event()

    def tick():
        while not done.is_set():
            ticks.append(1)
            time.sleep(0.001)

    t = threading.Thread(target=tick)
    t.start()
    try:
        before = len(ticks)
        plan = s.plan(planner="pso", seed=1, iterations=150)
        during = len(ticks) - before
    finally:
        done.set()
        t.join()
    assert plan.iterations == 150
    # With the GIL held for the whole plan the ticker could not run at all.
    assert during >= 5, f"the ticker ran {during} times during a {plan.elapsed_s:.2f} s plan"


def test_two_threads_plan_at_once_and_get_the_serial_results():
    s = Scenario.builtin("demo")
    serial = [s.plan(planner="pso", seed=k, iterations=30).missions[0].waypoints for k in (1, 2)]
    out = {}

    def run(k):
        out[k] = s.plan(planner="pso", seed=k, iterations=30).missions[0].waypoints

    threads = [threading.Thread(target=run, args=(k,)) for k in (1, 2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(timeout=120)
    assert np.array_equal(out[1], serial[0]) and np.array_equal(out[2], serial[1])


def test_sigint_stops_a_long_plan_with_keyboard_interrupt():
    s = Scenario.builtin("demo")
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        # Minutes of work without the signal.
        s.plan(planner="pso", seed=1, iterations=10**7, time_limit=300)
    elapsed = time.monotonic() - start
    timer.cancel()
    assert elapsed < 0.5 + 2.0, f"KeyboardInterrupt came {elapsed - 0.5:.2f} s after SIGINT"


def test_sigint_stops_an_optimizer_run():
    import tidepath

    timer = threading.Timer(0.5, lambda: signal.pthread_kill(threading.main_thread().ident, signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        tidepath.optimize("rastrigin", dim=30, algo="de", evaluations=10**10, time_limit=300)
    timer.cancel()
    assert time.monotonic() - start < 2.5

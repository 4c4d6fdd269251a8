#!/usr/bin/env python3
"""Interleaved rounds of PeriodicChuteBenchmark runs: every configuration in turn, round after
round, so that the host's slow spells fall on all of them alike (Documentation/Performance.md,
"The scene and the method"). Prints, per configuration, the best and the median time per
particle-step of the benchmark's own wall time, every round's, and each run's user CPU seconds.

    Drivers/Benchmarks/interleavedRounds.py [--binary PATH] ROUNDS 'label|arguments[|VAR=value ...]' ...

A setting BINARY=path runs that configuration with another build of the benchmark (a copy of the
binary before a change, to compare two versions of the code run for run).

e.g. (the developed flow at 3000 particles in single steps against 108000 in waves of 8):

    D=$TALUS_SHARED_DIR/peers/data/chute_B_flowing.data
    Drivers/Benchmarks/interleavedRounds.py 5 "3k|--nx 1 --ny 1 --data $D --end-time 0.2" \\
        "108k waves|--nx 6 --ny 6 --data $D --end-time 0.04 --wave-steps 8 --wave-strip 32"
"""
import os
import re
import resource
import statistics
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
binary = os.path.join(here, '..', '..', 'build', 'Drivers', 'Benchmarks', 'PeriodicChuteBenchmark')
args = sys.argv[1:]
if len(args) >= 2 and args[0] == '--binary':
    binary, args = args[1], args[2:]
if len(args) < 2 or not args[0].isdigit():
    sys.exit(__doc__)
rounds = int(args[0])
configs = []
for spec in args[1:]:
    parts = spec.split('|')
    if len(parts) < 2:
        sys.exit(f"interleavedRounds.py: '{spec}' is not 'label|arguments[|VAR=value ...]'")
    env = dict(os.environ)
    own = binary
    for setting in (parts[2].split() if len(parts) > 2 else []):
        if '=' not in setting:
            sys.exit(f"interleavedRounds.py: '{setting}' in '{spec}' is not VAR=value")
        name, value = setting.split('=', 1)
        if name == 'BINARY':
            own = value
        else:
            env[name] = value
    if not os.access(own, os.X_OK):
        sys.exit(f"interleavedRounds.py: no benchmark at {own} (build first: Scripts/build.sh, or --binary)")
    configs.append((parts[0], [own] + parts[1].split(), env))

times = {label: [] for label, _, _ in configs}
cpu = {label: [] for label, _, _ in configs}
line = re.compile(r'^benchmark: flowing (\d+)\s+steps (\d+)\s+wall ([\d.]+) s', re.M)
for r in range(rounds):
    for label, arguments, env in configs:
        before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
        run = subprocess.Popen(arguments + ['--progress-interval', '1e9'], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True, env=env)
        out, err = run.communicate()
        found = line.search(out)
        if run.returncode != 0 or not found:
            sys.exit(f"interleavedRounds.py: '{label}' failed (exit {run.returncode}):\n{err[-2000:]}")
        particles, steps, wall = int(found.group(1)), int(found.group(2)), float(found.group(3))
        times[label].append(wall / (particles * steps) * 1e9)
        cpu[label].append(resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime - before)
    print(f"round {r + 1} of {rounds} done", file=sys.stderr)
for label, _, _ in configs:
    t = times[label]
    print(f"{label:24s} best {min(t):6.1f} median {statistics.median(t):6.1f} ns  "
          f"{' '.join('%.1f' % x for x in t)}   user s: {' '.join('%.2f' % x for x in cpu[label])}")

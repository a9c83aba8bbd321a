#!/usr/bin/env python3
"""arm64.public_moves: every public move (tests/support/public_moves.hpp) planned with the arm64
cyber-plan under the emulator and with the native cyber-plan: the same outcome each time, and
durations equal to 1e-3 relative. Floating point is where the two can differ: with g++'s default
FMA contraction on AArch64 one move's duration was off by 2e-3, hence -ffp-contract=off in
cmake/toolchains/aarch64-linux-gnu.cmake; libm is another architecture's build.

    public_moves.py MOVES_PROGRAM ARM64_CYBER_PLAN NATIVE_CYBER_PLAN CONFIG EMULATOR...

MOVES_PROGRAM (arm64, run under the emulator) prints each move's label and cyber-plan arguments.
"""
import concurrent.futures
import json
import os
import subprocess
import sys
import time

RELATIVE_TOLERANCE = 1e-3


def plan(command, config, arguments):
    done = subprocess.run(command + ['--config', config, '--json'] + arguments,
                          capture_output=True, text=True, timeout=300)
    if done.returncode == 0:
        return ('ok', json.loads(done.stdout)['duration_s'])
    return ('exit %d' % done.returncode, done.stderr.strip())


def main():
    if len(sys.argv) < 6:
        sys.exit(__doc__)
    moves_program, arm64_plan, native_plan, config = sys.argv[1:5]
    emulator = sys.argv[5:]
    if not os.access(native_plan, os.X_OK):
        sys.exit('FAIL: no native cyber-plan at %s (tools/package --arch arm64 --test builds it; '
                 'or configure with -DCYBER_NATIVE_CYBER_PLAN=PATH)' % native_plan)
    listed = subprocess.run(emulator + [moves_program], capture_output=True, text=True, check=True)
    moves = [line.split(' ', 1) for line in listed.stdout.splitlines()]
    if not moves:
        sys.exit('FAIL: %s listed no moves' % moves_program)

    def both(move):
        label, arguments = move
        started = time.monotonic()
        arm64 = plan(emulator + [arm64_plan], config, arguments.split())
        emulated_s = time.monotonic() - started
        return label, arm64, plan([native_plan], config, arguments.split()), emulated_s

    failures = []
    worst = (0.0, '')
    planned = 0
    refused_alike = 0
    emulated_total_s = 0.0
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count()) as pool:
        for label, arm64, native, emulated_s in pool.map(both, moves):
            emulated_total_s += emulated_s
            if 'exit 2' in (arm64[0], native[0]):
                # Bad arguments or configuration: not the planner's answer, nothing compared.
                failures.append('%s: cyber-plan could not plan: arm64 %s, native %s' % (label, arm64[1], native[1]))
            elif arm64 != native and arm64[0] != 'ok':
                failures.append('%s: refused differently: arm64 %s (%s), native %s (%s)'
                                % (label, arm64[0], arm64[1], native[0], native[1]))
            elif arm64[0] != native[0]:
                failures.append('%s: arm64 %s (%s), native %s (%s)' % (label, arm64[0], arm64[1], native[0], native[1]))
            elif arm64[0] != 'ok':
                refused_alike += 1
            else:
                planned += 1
                relative = abs(arm64[1] - native[1]) / native[1]
                worst = max(worst, (relative, label))
                if relative > RELATIVE_TOLERANCE:
                    failures.append('%s: duration %.6f s on arm64, %.6f s native (relative %.2e)'
                                    % (label, arm64[1], native[1], relative))
    if planned == 0:
        failures.append('no move was planned by both')
    for failure in failures:
        print('FAIL ' + failure)
    print('public moves: %d listed, %d planned by both, %d refused by both alike; largest relative '
          'duration difference %.2e (%s); %.1f s of emulated planning'
          % (len(moves), planned, refused_alike, worst[0], worst[1], emulated_total_s))
    sys.exit(1 if failures else 0)


main()

#!/usr/bin/env python3
"""estimate_replay: the accuracy contract's error estimate replayed on a finished accuracy bench, under other constants.

    estimate_replay.py reports/benchmarks/accuracy.csv [--hp-accident 0.04,0.02,0.01] [--uniform-accident-power 2,3]

`gradcontact bench --part accuracy` writes every estimated quantity with the values of all its ladder's levels
(`level_values`) and its closed-form reference. This study recomputes each estimate from those values with the rule of
fem/accuracy/accuracy.h (the geometric tail |d_n| rho / (1 - rho) with its floors, its oscillation ratio, its accident
guard max(|d_n|, g |d_(n-1)|) and the uniform ladder's two-level safety factor; the clamped far field's truncation
term is left out, so a few estimates differ from the bench's), and prints:
  - how many replayed estimates differ from the bench's by more than 5 % (the check that the replay is the rule);
  - per ladder (hp for k >= 0, uniform for k < 0), group and what set the estimate (the floor ratio, the observed
    one, the oscillation ratio, the accident guard): the count, the median and the smallest estimate / true error,
    and how many are more than 10x the true error;
  - per variant of the accident guard (hp: g; uniform: g = rho_0^power): the share with true <= estimate, the worst
    true / estimate, the median and 90 % estimate / true error, and how many are above 10x.
It answers "would other constants make the estimate efficient (at most 10x) without losing reliability (never more
than 3x below)?" without solving anything again. The estimates of the ladder's last level only: a ladder that would
stop earlier under a looser rule is not replayed. Not a test.
"""
import argparse
import csv
import math
from collections import defaultdict

# The constants of fem/accuracy/accuracy.h.
RATIO_LIMIT = 0.8
OSCILLATION_RATIO = 0.5
HP_LOCAL_FLOOR = 0.5
TWO_LEVEL_SAFETY = 2
ZERO = 1e-12  # true errors below the closed forms' own precision count as zero


def uniform_floor(degree, s):
    base = 0.25 if degree <= 2 else 0.5
    return min(max(2 ** -(1 + s), base), RATIO_LIMIT) if s < 0 else base


def hp_floor(s):
    return 0.5 if s >= 0.9 else 1 / 3


def tail_estimate(values, floor, accident):
    """The geometric tail of values[-1] and what set it (accuracy.h, estimate())."""
    n = len(values) - 1
    if n == 0:
        return math.inf, 'one level'
    d_n = abs(values[n] - values[n - 1])
    tail, ratio, why = d_n, floor, 'floor'
    if n >= 2:
        d_prev = abs(values[n - 1] - values[n - 2])
        observed = d_n / d_prev if d_prev > 0 else (RATIO_LIMIT if d_n > 0 else 0)
        ratio = min(max(observed, floor), RATIO_LIMIT)
        why = 'observed' if observed > floor else 'floor'
        if (values[n] - values[n - 1]) * (values[n - 1] - values[n - 2]) < 0:
            why = 'oscillation' if ratio < OSCILLATION_RATIO else why
            ratio = max(ratio, OSCILLATION_RATIO)
        if accident * d_prev > d_n:
            why += ' + accident guard'
        tail = max(d_n, accident * d_prev)
    return tail * ratio / (1 - ratio), why


def replay(row, hp_accident, uniform_power):
    """(relative estimate, relative true error, what set it) of one bench row, or None."""
    k = float(row['k'])
    values = [float(x) for x in row['level_values'].split()]
    reference, true_error = float(row['reference']), float(row['true_error'])
    # The bench's relative errors divide by |value|, a pressure by the largest |p| sampled: recovered from the row.
    scale = abs(values[-1] - reference) / true_error if true_error > 0 else abs(values[-1])
    if scale == 0 or not values:
        return None
    if k >= 0:  # the hp ladder (power law: no jumps)
        floor = hp_floor(k)
        if row['quantity'].startswith('p('):
            floor = max(floor, HP_LOCAL_FLOOR)
        error, why = tail_estimate(values, floor, hp_accident)
    else:
        floor = uniform_floor(int(row['degree']), k)
        error, why = tail_estimate(values, floor, floor ** uniform_power)
        if len(values) == 2:
            error *= TWO_LEVEL_SAFETY
    return error / scale, true_error, why


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('csv')
    parser.add_argument('--hp-accident', default='0.04,0.02,0.01')
    parser.add_argument('--uniform-accident-power', default='2,3')
    args = parser.parse_args()
    with open(args.csv, newline='') as f:
        rows = list(csv.DictReader(f))

    differ, groups = 0, defaultdict(list)
    for row in rows:
        out = replay(row, 0.04, 2)
        if out is None:
            continue
        estimate, true_error, why = out
        bench = float(row['estimate'])
        if bench > 0 and abs(estimate / bench - 1) > 0.05:
            differ += 1
        if true_error > ZERO:
            ladder = 'hp' if float(row['k']) >= 0 else 'uniform'
            groups[(ladder, row['group'], why)].append(estimate / true_error)
    print(f'{len(rows)} estimates; {differ} replayed ones differ from the bench by more than 5 %')
    print('ladder | group | set by | count | median estimate/true | smallest | above 10')
    for (ladder, group, why), ratios in sorted(groups.items()):
        ratios.sort()
        print(f'{ladder} | {group} | {why} | {len(ratios)} | {ratios[len(ratios) // 2]:.1f} | {ratios[0]:.2f} | '
              f'{sum(1 for x in ratios if x > 10)}')

    print('hp guard | uniform guard | true <= estimate | worst true/estimate | median | 90 % | above 10')
    for hp_accident in (float(x) for x in args.hp_accident.split(',')):
        for power in (int(x) for x in args.uniform_accident_power.split(',')):
            ratios = sorted(out[0] / out[1] for out in (replay(r, hp_accident, power) for r in rows)
                            if out is not None and out[1] > ZERO)
            n = len(ratios)
            print(f'{hp_accident:g} | rho_0^{power} | {100 * sum(1 for x in ratios if x >= 1) / n:.1f} % | '
                  f'{1 / ratios[0]:.2f} | {ratios[n // 2]:.1f} | {ratios[int(0.9 * n)]:.1f} | '
                  f'{sum(1 for x in ratios if x > 10)} of {n}')


if __name__ == '__main__':
    main()

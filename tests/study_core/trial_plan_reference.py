#!/usr/bin/env python3
"""An independent reference of the seeded trial order (study/trial_plan.hpp's definition), in
Python integers, written from the header's definition and not from the C++ code: splitmix64
(Vigna, prng.di.unimi.it/splitmix64.c), FNV-1a-64, the draw below n that rejects outputs under
2^64 mod n, Fisher-Yates from the top, derive, and the matching and location plans.

Prints one line per case, "CASE: VALUE"; trial_plan_reference_test.cpp (ctest) runs this script,
computes every CASE with the C++ code and compares the VALUE. Python 3's standard library only.

    python3 trial_plan_reference.py            the cases
    python3 trial_plan_reference.py --check    also checks the values trial_plan_test.cpp pins
"""
import sys

MASK = (1 << 64) - 1
GOLDEN = 0x9E3779B97F4A7C15


def mix64(z):
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
    return z ^ (z >> 31)


class SplitMix64:
    def __init__(self, seed):
        self.state = seed & MASK

    def next(self):
        self.state = (self.state + GOLDEN) & MASK
        return mix64(self.state)

    def below(self, n):
        reject_below = (1 << 64) % n
        while True:
            r = self.next()
            if r >= reject_below:
                return r % n


def fnv1a64(text):
    h = 0xCBF29CE484222325
    for byte in text.encode('utf-8'):
        h = ((h ^ byte) * 0x100000001B3) & MASK
    return h


def participant_seed(study_seed, participant):
    return mix64(mix64((study_seed + GOLDEN) & MASK) ^ fnv1a64(participant))


def derive(seed, purpose, index):
    return mix64((mix64(seed ^ mix64((purpose * GOLDEN) & MASK)) + index * GOLDEN) & MASK)


def shuffled_indices(n, seed):
    order = list(range(n))
    rng = SplitMix64(seed)
    for i in range(n, 1, -1):
        j = rng.below(i)
        order[i - 1], order[j] = order[j], order[i - 1]
    return order


def matching_plan(study_seed, repetitions, set_sizes, participant):
    """(set, image) per trial: per set, images 0..m-1 repeated `repetitions` times, permuted."""
    seed = participant_seed(study_seed, participant)
    plan = []
    for s, size in enumerate(set_sizes):
        block = [(s, i) for _ in range(repetitions) for i in range(size)]
        plan += [block[k] for k in shuffled_indices(len(block), derive(seed, 1, s))]
    return plan


def location_plan(study_seed, per_metaphor, order, participant, metaphors='RT'):
    """(metaphor letter, data seed) per trial."""
    seed = participant_seed(study_seed, participant)
    if order == 'blocked':
        letters = [metaphors[m] for m in shuffled_indices(len(metaphors), derive(seed, 2, 0)) for _ in range(per_metaphor)]
    else:
        everything = [m for m in metaphors for _ in range(per_metaphor)]
        letters = [everything[k] for k in shuffled_indices(len(everything), derive(seed, 3, 0))]
    return [(letter, derive(seed, 4, k + 1)) for k, letter in enumerate(letters)]


def cases():
    out = []
    for n in (0, 1, 2, 3, 7, 10, 33, 100):
        for seed in (0, 1, 42, 2024, GOLDEN, MASK):
            out.append(f'shuffle {n} {seed}: ' + ' '.join(map(str, shuffled_indices(n, seed))))
    ids = ('P01', 'P02', 'x', 'tablet-7', 'demo', 'A' * 64)
    for seed in (0, 1, 7, 2024, MASK):
        for pid in ids:
            out.append(f'participant_seed {seed} {pid}: {participant_seed(seed, pid)}')
    # The tests' study (sets of 4 and 3 images) and the shipped example's shape (two sets of 4).
    for seed, reps, sizes in ((2024, 5, (4, 3)), (2024, 1, (4, 3)), (2024, 5, (4, 4)), (1, 3, (2, 5, 3))):
        for pid in ids:
            plan = matching_plan(seed, reps, sizes, pid)
            sizes_text = ','.join(map(str, sizes))
            out.append(f'matching {seed} {reps} {sizes_text} {pid}: ' + ' '.join(f'{s}:{i}' for s, i in plan))
    for order in ('blocked', 'interleaved'):
        for seed, per in ((7, 7), (1, 3), (2024, 20)):
            for pid in ('P01', 'P02', 'P03', 'demo'):
                plan = location_plan(seed, per, order, pid)
                out.append(f'location {order} {seed} {per} {pid}: ' + ' '.join(f'{m}:{s:016X}' for m, s in plan))
    return out


def check_pins():
    """The values trial_plan_test.cpp pins, from this reference."""
    problems = []

    def expect(what, got, want):
        if got != want:
            problems.append(f'{what}: reference {got}, pinned {want}')

    expect('shuffled_indices(10, 0)', shuffled_indices(10, 0), [6, 3, 2, 9, 8, 1, 4, 7, 0, 5])
    expect('shuffled_indices(8, 42)', shuffled_indices(8, 42), [3, 1, 6, 2, 4, 0, 7, 5])
    expect('participant_seed(7, P01)', participant_seed(7, 'P01'), 15220198599442192890)
    expect('participant_seed(2024, P01)', participant_seed(2024, 'P01'), 0x3D0CCE5EC8E439B1)
    expect('splitmix64 from 0', SplitMix64(0).next(), 0xE220A8397B1DCDAF)  # Vigna's published first output
    for pid, want in (('P01', '23101220313302102130' '022120200112110'), ('P02', '01021203330122133012' '011101010222202')):
        expect(f'matching plan of {pid}', ''.join(str(i) for _, i in matching_plan(2024, 5, (4, 3), pid)), want)
    for pid, want in (('P01', 'RRRRRRRTTTTTTT'), ('P02', 'TTTTTTTRRRRRRR'), ('P03', 'RRRRRRRTTTTTTT')):
        expect(f'blocked plan of {pid}', ''.join(m for m, _ in location_plan(7, 7, 'blocked', pid)), want)
    interleaved = location_plan(7, 7, 'interleaved', 'P01')
    expect('interleaved plan of P01', ''.join(m for m, _ in interleaved), 'RRTTRTRRRTTTRT')
    seeds = [0x711D6FFDDF81414C, 0x342DBCA20CCA49FE, 0xB56FC2A90E46560E, 0xA9B4D4B71038012E, 0xECBF0A4A65EFB320,
             0xCEAF31B205A48DFE, 0xD01082548A1436AA, 0xA29D8C2D92DC91D3, 0xE5920097BD2C0ED8, 0xD6C5068E939051B3,
             0xF19604B695CC4641, 0xC8641F8CF01F4070, 0x81BF85C52D913D71, 0xBDEA090F15188940]
    expect('data seeds of P01', [s for _, s in interleaved], seeds)
    return problems


if __name__ == '__main__':
    if '--check' in sys.argv[1:]:
        problems = check_pins()
        for p in problems:
            print('MISMATCH ' + p)
        if problems:
            sys.exit(1)
    print('\n'.join(cases()))

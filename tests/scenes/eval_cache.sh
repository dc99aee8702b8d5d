#!/bin/sh
# ctest scenes.eval_keeps_fe_answers_between_runs: the second process answers an FE request from the cache of the
# first, with the same digits, and a different "id" does not make it another request. Arguments: the gradcontact
# executable and a scratch folder.
set -e
exe=$1
dir=$2
rm -rf "$dir"
request='"case": "paraboloid", "material": {"E0": 1e9, "c0": 1e-3, "k": 0.3, "nu": 0.3}, "geometry": {"R": 1e-2}, "a": 1e-4, "quantity": "force", "method": "fe", "tolerance": 1e-3'
first=$(echo "{\"id\": 1, $request}" | GRADCONTACT_EVAL_CACHE="$dir" "$exe" eval)
[ "$(ls "$dir" | wc -l)" -eq 1 ] || { echo "no cache entry after the first run"; exit 1; }
second=$(echo "{\"id\": 2, $request}" | GRADCONTACT_EVAL_CACHE="$dir" "$exe" eval)
[ "${first#*,}" = "${second#*,}" ] || { echo "the cached answer differs: $first / $second"; exit 1; }
[ "$(ls "$dir" | wc -l)" -eq 1 ] || { echo "the second run stored another entry"; exit 1; }
uncached=$(echo "{\"id\": 3, $request}" | GRADCONTACT_EVAL_CACHE="" "$exe" eval)
[ "${first#*,}" = "${uncached#*,}" ] || { echo "a fresh solve differs from the cached answer: $first / $uncached"; exit 1; }
echo "cached answer: $second"

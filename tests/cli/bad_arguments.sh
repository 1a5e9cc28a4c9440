#!/bin/sh
# The exit-code table (docs/cli.md) against every subcommand's bad-argument paths: each value flag
# with bad and out-of-domain values, each value flag missing its value, unknown flags and flags of
# another subcommand all exit 2 with a message on stderr starting "oasis: " and nothing on stdout;
# a bad OASIS_SHADER_DIR exits 1 naming the variable, writing nothing. Each case has a time limit
# (a hang fails it). Usage: bad_arguments.sh OASIS_EXECUTABLE SCRATCH_DIR [PART]
# PART splits the ~600 cases so that each ctest entry stays well inside its time limit under the
# sanitizer build (a process start there costs ~0.5 s): "scene:COMMAND" runs the scene-option table
# against one subcommand (COMMAND "main" for the bare main job), "rest" runs everything else; no
# PART runs all of it.
oasis=$1
scratch=$2
part=${3:-all}
rm -rf "$scratch" && mkdir -p "$scratch" || exit 1
cases=0
failures=0
environment=  # assignments for env(1) before oasis: none but in the OASIS_SHADER_DIR cases

fail() {
    echo "FAIL: $*"
    failures=$((failures + 1))
}

# expect CODE ARGS...: runs oasis with ARGS and checks the exit code and the message.
expect() {
    code=$1
    shift
    cases=$((cases + 1))
    # shellcheck disable=SC2086
    timeout 60 env $environment "$oasis" "$@" > "$scratch/stdout" 2> "$scratch/stderr"
    got=$?
    if [ "$got" -ne "$code" ]; then
        fail "oasis $* exited $got, expected $code; stderr: $(head -c 300 "$scratch/stderr")"
    elif ! head -n 1 "$scratch/stderr" | grep -q '^oasis: '; then
        fail "oasis $*: no 'oasis: ' message on stderr (got '$(head -c 200 "$scratch/stderr")')"
    elif [ "$code" -eq 2 ] && [ -s "$scratch/stdout" ]; then
        fail "oasis $*: a usage error printed to stdout: $(head -c 200 "$scratch/stdout")"
    fi
}

# Bad values of every scene option (every subcommand takes them), out-of-domain numbers included.
# One case per line: FLAG VALUE (a value may contain spaces only where it says so).
scene_cases() {
    cat <<'EOF'
--size|0x0
--size|abc
--size| 64x36
--size|+32x+18
--size|32x18 
--size|32769x18
--size|99999999999x10
--time|soon
--time|1e300
--time|-1e300
--time|nan
--time|inf
--time|5000001
--time|0x10
--hour|25
--hour|-0.5
--hour|6.9e10
--camera|1,2,3
--camera|1,2,3,4,5,6
--camera|68719476110,50,0,0,0
--camera|1e300,100,0,0,-5
--camera|0,1e308,0,0,0
--camera|0,50,-6.9e10,0,0
--camera|0,50,0,nan,0
--camera|0,50,0,0,91
--camera|0,5000,0,0,0
--camera|0,50,0,0,
--gbuffer|nope
--depth|nope
--reflections|maybe
--water-level|201
--water-level|-1e308
--water-level|deep
--ripples|-1
--ripples|51
--ripples|4.9e-324x
--absorption|11
--absorption|-0.001
--vegetation|maybe
--billboards|half
--reflection-bounds|maybe
--reflection-resolution|eighth
--reflection-resolution|Half
--reflection-resolution|0.5
--reflection-plant-cull|maybe
--reflection-plant-cull|On
--reflection-plant-cull|still
--tone-map|maybe
--depth-read|inplace
--shadows|maybe
--shadows|ON
--shadow-quality|ultra
--vegetation-density|4.5
--vegetation-density|-1
--wind|3.5
--wind|gale
--lights|4097
--lights|-1
--lights|+3
--lights|1.5
--lights-path|nope
--light-method|nope
--light-method|Tiled
--force|nope
EOF
}

# Options that take a value (each is tried with its value missing).
value_flags="--size --time --hour --camera --gbuffer --depth --reflections --reflection-bounds --reflection-resolution --reflection-plant-cull --tone-map --depth-read --shadows --shadow-quality --water-level --ripples --absorption
  --vegetation --vegetation-density --wind --lights --lights-path --light-method --force --pipeline --view --out --stencil-view
  --stop-before --out-dir --frames --seed --until-ci --driver --reference --driver-timeout"

for command in main render compare caps bench window; do
    [ "$part" = all ] || [ "$part" = "scene:$command" ] || continue
    [ "$command" = main ] && command=
    set -- ${command:+"$command"}
    expect 2 "$@" --bogus
    expect 2 "$@" -x
    for flag in $value_flags; do expect 2 "$@" "$flag"; done
    scene_cases > "$scratch/cases"  # read in this shell, not a pipe's subshell: the counters survive
    while IFS='|' read -r flag value; do expect 2 "$@" "$flag" "$value"; done < "$scratch/cases"
done
case $part in
    all|rest) ;;
    scene:main|scene:render|scene:compare|scene:caps|scene:bench|scene:window)
        echo "bad arguments: $cases cases, $failures failures"
        [ "$failures" -eq 0 ]
        exit ;;
    *) echo "bad_arguments.sh: unknown part '$part'"; exit 1 ;;
esac

# Options of one subcommand under another.
for command in compare caps bench window ""; do
    set -- ${command:+"$command"}
    expect 2 "$@" --pipeline forward
    expect 2 "$@" --view albedo
    expect 2 "$@" --out x.png
    expect 2 "$@" --stencil-view texturing
    expect 2 "$@" --stop-before ToneMapPass
done
for command in render window caps; do
    expect 2 $command --frames 3
    expect 2 $command --seed 3
    expect 2 $command --until-ci 3
    expect 2 $command --out-dir "$scratch/never"
    expect 2 $command --passes
done
for command in render window; do expect 2 $command --json; done
for command in "" render compare caps window; do expect 2 ${command:+"$command"} --quick; done
for command in "" caps window probe; do expect 2 ${command:+"$command"} --capture; done
expect 2 bench --passes
expect 2 bench --until-ci 3
expect 2 bench --depth standard
expect 2 bench --size 64x36
expect 2 bench --camera 0,50,0,0,0
expect 2 paint
expect 2 render render

# Values only `render`, compare, bench and the main job check.
expect 2 render --pipeline sideways
expect 2 render --view nope
expect 2 render --stencil-view nope
expect 2 render --stop-before Nope
expect 2 render --pipeline forward --stop-before LightingPass
expect 2 render --out "$scratch/x.jpg"
expect 2 render --out "$scratch/x"
expect 2 render --out ""
for command in "" compare bench; do
    set -- ${command:+"$command"}
    expect 2 "$@" --frames 0
    expect 2 "$@" --frames 1001
    expect 2 "$@" --frames many
    expect 2 "$@" --out-dir ""
    # --seed: an integer in [0, 999999]; malformed, negative and huge values are refused.
    expect 2 "$@" --seed -1
    expect 2 "$@" --seed 1000000
    expect 2 "$@" --seed 99999999999999999999
    expect 2 "$@" --seed 1.5
    expect 2 "$@" --seed many
done
# --until-ci: a percent in [0.5, 50] (compare and the main job).
for command in "" compare; do
    set -- ${command:+"$command"}
    expect 2 "$@" --until-ci 0
    expect 2 "$@" --until-ci 0.1
    expect 2 "$@" --until-ci 51
    expect 2 "$@" --until-ci -3
    expect 2 "$@" --until-ci nan
    expect 2 "$@" --until-ci 3%
done
expect 2 compare --driver llvmpipe --driver softpipe --seed 3
expect 2 compare --driver llvmpipe --driver softpipe --until-ci 3
[ -e "$scratch/x.jpg" ] && fail "render wrote a .jpg"

# compare --driver / --reference: unknown set-ups (listing the valid ones), one or three set-ups,
# both forms at once, a reference that is no readable PNG or not the --size asked for; nothing rendered.
expect 2 compare --driver nope --driver llvmpipe
grep -q 'one of: native, llvmpipe, zink, softpipe' "$scratch/stderr" || fail "unknown --driver does not list the set-ups: $(cat "$scratch/stderr")"
expect 2 compare --driver llvmpipe
expect 2 compare --driver llvmpipe --driver zink --driver softpipe
expect 2 compare --driver llvmpipe --driver llvmpipe --reference "$scratch/ref.png"
expect 2 compare --driver llvmpipe --driver llvmpipe --frames 3
expect 2 render --driver llvmpipe
# --driver-timeout: seconds in [0.1, 86400], only with --driver / --reference.
for value in 0 0.09 -1 86401 1e300 nan soon 10s ""; do
    expect 2 compare --driver llvmpipe --driver zink --driver-timeout "$value" --out-dir "$scratch/driver-never"
    grep -q "driver-timeout expects seconds in \[0.1, 86400\], got '$value'" "$scratch/stderr" ||
        fail "--driver-timeout '$value': $(cat "$scratch/stderr")"
done
expect 2 compare --driver-timeout 5 --frames 1
grep -q 'belongs to `oasis compare --driver/--reference`' "$scratch/stderr" || fail "plain compare --driver-timeout: $(cat "$scratch/stderr")"
expect 2 render --driver-timeout 5
expect 2 caps --reference "$scratch/ref.png"
expect 2 compare --reference "$scratch/ref.jpg"
expect 2 compare --reference "$scratch/missing.png" --out-dir "$scratch/driver-never"
echo "not a picture" > "$scratch/text.png"
expect 2 compare --reference "$scratch/text.png" --out-dir "$scratch/driver-never"
grep -q 'not a PNG' "$scratch/stderr" || fail "a text file as --reference: $(cat "$scratch/stderr")"
"$oasis" render --size 32x18 --legend off --out "$scratch/small.png" > /dev/null 2>&1 || fail "render of a 32x18 reference failed"
expect 2 compare --reference "$scratch/small.png" --size 64x36 --out-dir "$scratch/driver-never"
grep -q '32x18 but --size is 64x36' "$scratch/stderr" || fail "a reference of another size: $(cat "$scratch/stderr")"
[ -e "$scratch/driver-never" ] && fail "compare --reference with bad input created its output directory"
mkdir -p "$scratch/sent" && cp "$scratch/small.png" "$scratch/sent/here.png"
expect 2 compare --reference "$scratch/sent/here.png" --out-dir "$scratch/sent"
cmp -s "$scratch/small.png" "$scratch/sent/here.png" || fail "compare --reference overwrote the reference with its own frame"

# --capture outside RenderDoc: exit 1 saying so, before rendering or writing anything.
for command in "render --size 16x9 --out $scratch/capture.png" "compare --size 16x9 --frames 1 --out-dir $scratch/capture" \
               "bench --quick --out-dir $scratch/capture-bench"; do
    # shellcheck disable=SC2086
    expect 1 $command --capture
    grep -q 'not running under RenderDoc' "$scratch/stderr" || fail "oasis $command --capture: $(cat "$scratch/stderr")"
done
[ -e "$scratch/capture.png" ] && fail "render --capture without RenderDoc wrote its PNG"

# A bad OASIS_SHADER_DIR: exit 1 naming the variable, for every command that renders or reports.
mkdir -p "$scratch/no-shaders"
for directory in /nonexistent "$scratch/no-shaders" "$oasis" ""; do
    for command in "render --size 16x9 --out $scratch/env.png" "compare --size 16x9 --frames 1 --out-dir $scratch/env" \
                   "caps" "bench --quick --out-dir $scratch/env-bench" "--size 16x9 --frames 1 --out-dir $scratch/env-main"; do
        environment="-u DISPLAY -u WAYLAND_DISPLAY OASIS_SHADER_DIR=$directory"
        # shellcheck disable=SC2086
        expect 1 $command
        environment=
        grep -q 'OASIS_SHADER_DIR' "$scratch/stderr" || fail "OASIS_SHADER_DIR='$directory' oasis $command: not named: $(cat "$scratch/stderr")"
    done
    [ -e "$scratch/env.png" ] && fail "render wrote a file with OASIS_SHADER_DIR='$directory'"
done

echo "bad arguments: $cases cases, $failures failures"
[ "$failures" -eq 0 ]

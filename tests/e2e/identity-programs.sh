# Sourced by the identity checks (datapath-identity.sh, threads-identity.sh)
# after checks.sh: every end-to-end program of tolerances.txt, each through
# the caller's command.
#   each_program CMD [ARG...]
# runs CMD ARG... NAME PROGRAM ARGS... for each line of tolerances.txt, with
# PROGRAM the program's path under $build/tests/e2e and NAME and ARGS as
# the line gives them (the list is kept as $out/list).
each_program() {
    cmd=$*
    grep -v '^#' "$here/tolerances.txt" | grep -v '^[[:space:]]*$' > "$out/list"
    while IFS= read -r line; do
        spec=${line%%|*}
        # shellcheck disable=SC2086
        set -- $spec
        name=$1 prog=$2
        shift 2
        $cmd "$name" "$build/tests/e2e/$prog" "$@"
    done < "$out/list"
}

# Sourced by tools/demo.sh and tests/e2e/run.sh: fp_run_driver DRIVER PROG ARGS
# runs PROG through one GL driver on EGL surfaceless.  Expects $root (the
# repository).
#
# Through the launcher (./fixpipe run --driver D -- PROG ...) when it can
# serve the driver.  The launcher takes softpipe from our own Mesa build in
# .fixpipe/prefix; before that exists (or with FP_SYSTEM_MESA=1) llvmpipe and
# softpipe come from Debian's system Mesa, the same 22.3.6, so the tests can
# be validated without the driver.

fp_run_driver() {
    _drv=$1
    shift
    _prefix=${root:?fp-run-driver.sh needs $root}/.fixpipe/prefix
    if [ "${FP_SYSTEM_MESA:-0}" != 1 ] && [ -x "$root/fixpipe" ] &&
       { [ "$_drv" = llvmpipe ] || [ -e "$_prefix/lib/libGL.so.1" ] || [ "$_drv" = fixpipe ]; }; then
        "$root/fixpipe" run --no-xvfb --driver "$_drv" -- "$@"
        return
    fi
    case $_drv in
    fixpipe)
        echo "error: fixpipe needs ./fixpipe and its Mesa build (./fixpipe setup)" >&2
        return 127 ;;
    *)
        env -u LD_LIBRARY_PATH -u LIBGL_DRIVERS_PATH EGL_PLATFORM=surfaceless \
            GALLIUM_DRIVER="$_drv" "$@" ;;
    esac
}

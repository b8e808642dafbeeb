#!/bin/sh
# LLVM starts at a process's first compiled shader, not when the driver is loaded
# (mesa/llvm-ctors.ld, mesa/patches/0006, docs/jit.md):
#  - the driver's LLVM constructors sit in gallivm_llvm_ctors, not in .init_array;
#  - a program too small for any shader to get hot never runs gallivm's set-up nor one of
#    LLVM's constructors (watched with gdb on lp_build_init and LLVMContextImpl.cpp's);
#  - the same program with every shader compiled (FIXPIPE_DEBUG=jitall) runs that
#    constructor exactly once, and draws the same picture byte for byte.
# One line per check, then "N passed, N failed"; exit 1 on a failure.
checks=llvm-start
. "$(dirname "$0")/checks.sh"
driver=${FIXPIPE_WORK:-$root/.fixpipe}/prefix/lib/dri/swrast_dri.so

# entries (8 bytes each) of a section of the driver, 0 when it has none
entries() {
    readelf -SW "$driver" | awk -v s="$1" '$2 == s { print int(("0x" $6) / 8); f = 1 }
        END { if (!f) print 0 }'
}
deferred=$(entries gallivm_llvm_ctors)
at_load=$(entries .init_array)
if [ "$deferred" -ge 100 ] && [ "$at_load" -le 16 ]; then
    pass "driver: $deferred LLVM constructors deferred, $at_load run at load"
else
    fail "driver: $deferred LLVM constructors deferred (want >= 100), $at_load run at load (want <= 16)"
fi

# watch MODE: runs the small gouraud picture under gdb; prints how often gallivm's set-up
# and LLVMContextImpl.cpp's constructor ran, or fails
watch() {
    mode=$1
    FIXPIPE_DEBUG=$mode "$root/fixpipe" run --no-xvfb --driver fixpipe -- \
        gdb -q -batch -ex 'set breakpoint pending on' \
        -ex 'dprintf lp_build_init,"fixpipe-watch lp_build_init\n"' \
        -ex "dprintf '_GLOBAL__sub_I_LLVMContextImpl.cpp',\"fixpipe-watch llvm_ctor\\n\"" \
        -ex run -ex 'info breakpoints' \
        --args "$build/tests/e2e/e2e-gouraud" -o "$out/gouraud.${mode:-tiered}.png" --size 32 \
        > "$out/${mode:-tiered}.log" 2>&1
    if ! grep -q "exited normally" "$out/${mode:-tiered}.log" ||
       [ "$(grep -c '^[0-9].*dprintf' "$out/${mode:-tiered}.log")" != 2 ]; then
        echo "no-run"
        return
    fi
    echo "$(grep -c '^fixpipe-watch lp_build_init' "$out/${mode:-tiered}.log")" \
         "$(grep -c '^fixpipe-watch llvm_ctor' "$out/${mode:-tiered}.log")"
}

set -- $(watch "")
if [ "$1" = no-run ]; then
    fail "small picture, tiered: did not run under gdb ($out/tiered.log)"
elif [ "$1" = 0 ] && [ "$2" = 0 ]; then
    pass "small picture, tiered: LLVM never started"
else
    fail "small picture, tiered: lp_build_init ran $1 times, LLVMContextImpl.cpp's constructor $2"
fi

set -- $(watch jitall)
if [ "$1" = no-run ]; then
    fail "small picture, jitall: did not run under gdb ($out/jitall.log)"
elif [ "$1" -ge 1 ] && [ "$2" = 1 ]; then
    pass "small picture, jitall: LLVM's constructors ran once, at the first compilation"
else
    fail "small picture, jitall: lp_build_init ran $1 times, LLVMContextImpl.cpp's constructor $2 (want 1)"
fi

if cmp -s "$out/gouraud.tiered.png" "$out/gouraud.jitall.png"; then
    pass "small picture: the same bytes interpreted and compiled"
else
    fail "small picture: interpreted and compiled pictures differ"
fi

checks_end

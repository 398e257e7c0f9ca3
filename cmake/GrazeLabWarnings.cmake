# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
# The warning flags of every target the project compiles, in one place. CI builds with
# -DGRAZELAB_WERROR=ON: a warning fails it.
option(GRAZELAB_WERROR "Treat compiler warnings as errors (CI builds with it)" OFF)

function(grazelab_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic $<$<BOOL:${GRAZELAB_WERROR}>:-Werror>
    # under the sanitizers GCC 12 sees libstdc++'s std::stop_source as maybe uninitialized
    # (grazelab-cli's main): a known false positive of the instrumented code, off there only
    $<$<BOOL:${GRAZELAB_SANITIZE}>:-Wno-maybe-uninitialized>)
endfunction()

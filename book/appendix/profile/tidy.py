import sys
# Shortens perf's stacks for a readable flame graph: rayon's recursive splitting
# is one frame, a kernel entry ends the stack as "kernel", the start-up frames go.
KERNEL = ('asm_exc_page_fault', 'entry_SYSCALL_64_after_hwframe', 'asm_sysvec_apic_timer_interrupt', 'asm_common_interrupt')
SKIP = ('raybook', '_start', '__libc_start_main@@GLIBC_2.34', '__libc_start_call_main', 'main', 'clone3', 'start_thread', '[unknown]')
NAMES = [('raybook::wide::eight::', 'wide::eight::'), ('raybook::wide::traverse::<impl raybook::wide::WideBvh>::', 'wide::'), ('<raybook::wide::WideBvh as ch04_shadows::World>::', 'wide::World::'), ('raybook::wide::traverse::', 'wide::'), ('raybook::wide::WideBvh::', 'wide::'), ('ch05_reflection::', 'ch05::'), ('ch02_hits::triangle::', 'ch02::'), ('ch02_hits::', 'ch02::'), ('ch06_refraction::', 'ch06::')]
for line in sys.stdin:
    stack, n = line.rstrip('\n').rsplit(' ', 1)
    out = []
    for f in stack.split(';'):
        if f.startswith(('raybook-', 'core::ops::function', 'std::sys')) or f in SKIP or 'thread_start' in f:
            continue
        if f in KERNEL:
            out.append('kernel (page faults, system calls)')
            break
        if 'rayon' in f or f.startswith('workbench::cli::render_with_bar'):
            f = 'rayon (threads, splitting the rows)'
            if out and out[-1] == f:
                continue
        for long, short in NAMES:
            f = f.replace(long, short)
        out.append(f)
    print(';'.join(out) or 'other', n)

/* cortex_m4_startup.S - bare-metal harness for the runtime tests on QEMU's mps2-an386 (Cortex-M4):
 * vector table, reset handler (FPU on when built for it, .bss zeroed, semihosting I/O opened, main, exit
 * with its status through semihosting), and a fault handler that stops QEMU with a run-time error. */
  .syntax unified
  .cpu cortex-m4
  .thumb

  .section .vectors, "a"
  .word __stack_top
  .word reset_handler
  .rept 14
  .word fault_handler
  .endr

  .text
  .thumb_func
  .global reset_handler
reset_handler:
#if defined(__ARM_FP)
  ldr r0, =0xE000ED88          /* CPACR: full access to CP10 and CP11 (the FPU) */
  ldr r1, [r0]
  orr r1, r1, #(0xF << 20)
  str r1, [r0]
  dsb
  isb
#endif
  ldr r0, =__bss_start__
  ldr r1, =__bss_end__
  movs r2, #0
1:
  cmp r0, r1
  bhs 2f
  str r2, [r0], #4
  b 1b
2:
  bl initialise_monitor_handles
  bl main
  bl exit
  b .

  .thumb_func
  .global fault_handler
fault_handler:
  movs r0, #0x18               /* SYS_EXIT */
  ldr r1, =0x20023             /* ADP_Stopped_RunTimeError */
  bkpt 0xab
  b .

  .thumb_func
  .global _init
_init:
  bx lr
  .thumb_func
  .global _fini
_fini:
  bx lr

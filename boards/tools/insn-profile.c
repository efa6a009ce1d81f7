/*
 * insn-profile: a QEMU TCG plugin that counts executed guest instructions
 * per program counter, for boards/profile-m0.sh.
 *
 * How it counts: when QEMU translates a block of guest code (a TB: straight
 * code up to a branch), the plugin records the block's instructions (address,
 * size, first 32 bits of encoding) and registers a callback that runs every
 * time the block is entered. The callback adds one to the block's count and
 * looks at the block entered before it: if that one did not fall through
 * into this one (the next block does not start right after its last
 * instruction), its last instruction branched, so per block we also know how
 * often its final branch was taken. That is what a cycle estimate for a
 * conditional branch needs (1 cycle not taken, 2 taken on a Cortex-M0+).
 * At exit the plugin writes one line per translated instruction:
 *
 *     <pc hex> <size> <encoding hex> <executions> <taken>
 *
 * (This plugin is for Thumb code: see the size correction in
 * on_translation.)
 *
 * `taken` is non-zero only for the last instruction of a block. A PC
 * translated more than once (a block entered in its middle, or translated
 * again) has one line per translation; the reader adds them up.
 *
 * Window: with `on=ADDR,off=ADDR` (hex guest addresses of two functions'
 * entries) only blocks entered between an entry of `on` and the next entry
 * of `off` are counted, so a firmware can mark the code it measures;
 * without them everything is counted.
 *
 * Limits: a block left in its middle (an exception, or QEMU's icount
 * restart of a block with an I/O access) still counts all its instructions,
 * and an interrupt taken between two blocks counts as a taken branch; both
 * are rare here (SysTick wraps every 2^24 ticks, I/O only in the counter and
 * the semihosting output).
 *
 * Build (no QEMU headers needed, see below):
 *     cc -shared -fPIC -O2 -o libinsn-profile.so insn-profile.c
 * Run:
 *     qemu-system-arm ... -plugin ./libinsn-profile.so,out=FILE[,on=ADDR,off=ADDR]
 *
 * Single-threaded by design: QEMU runs one vCPU thread with -icount.
 */
#include <inttypes.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/*
 * The plugin API of QEMU 7.2 (API version 1), as documented in its
 * include/qemu/qemu-plugin.h. Debian ships no such header, so the few
 * declarations this plugin uses are written out here. qemu_info_t is only
 * passed on, never read, so it stays an incomplete type.
 */
typedef uint64_t qemu_plugin_id_t;
typedef struct qemu_info_t qemu_info_t;
struct qemu_plugin_tb;
struct qemu_plugin_insn;

enum qemu_plugin_cb_flags {
    QEMU_PLUGIN_CB_NO_REGS,
    QEMU_PLUGIN_CB_R_REGS,
    QEMU_PLUGIN_CB_RW_REGS,
};

typedef void (*qemu_plugin_udata_cb_t)(qemu_plugin_id_t id, void *userdata);
typedef void (*qemu_plugin_vcpu_udata_cb_t)(unsigned int vcpu_index,
                                            void *userdata);
typedef void (*qemu_plugin_vcpu_tb_trans_cb_t)(qemu_plugin_id_t id,
                                               struct qemu_plugin_tb *tb);

void qemu_plugin_register_vcpu_tb_trans_cb(qemu_plugin_id_t id,
                                           qemu_plugin_vcpu_tb_trans_cb_t cb);
void qemu_plugin_register_vcpu_tb_exec_cb(struct qemu_plugin_tb *tb,
                                          qemu_plugin_vcpu_udata_cb_t cb,
                                          enum qemu_plugin_cb_flags flags,
                                          void *userdata);
void qemu_plugin_register_atexit_cb(qemu_plugin_id_t id,
                                    qemu_plugin_udata_cb_t cb,
                                    void *userdata);
size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb *tb);
struct qemu_plugin_insn *qemu_plugin_tb_get_insn(const struct qemu_plugin_tb *tb,
                                                 size_t idx);
const void *qemu_plugin_insn_data(const struct qemu_plugin_insn *insn);
size_t qemu_plugin_insn_size(const struct qemu_plugin_insn *insn);
uint64_t qemu_plugin_insn_vaddr(const struct qemu_plugin_insn *insn);
void qemu_plugin_outs(const char *string);

#define EXPORT __attribute__((visibility("default")))

/* The API version this plugin is written against (QEMU 7.2 accepts 0..1). */
EXPORT int qemu_plugin_version = 1;

/* One translated instruction. */
struct insn {
    uint64_t pc;
    uint32_t encoding; /* little-endian bytes as one word; 16-bit: low half */
    uint32_t size;
};

/* One translated block. */
struct block {
    struct block *next_translated; /* list of every block, for the report */
    uint64_t execs;
    uint64_t taken;       /* entries of another block not at `fallthrough` */
    uint64_t start;       /* PC of the first instruction */
    uint64_t fallthrough; /* PC right after the last instruction */
    size_t n;
    struct insn insns[];
};

static struct block *all_blocks;
static struct block *last_entered;
static const char *out_path = "insn-profile.txt";
static uint64_t window_on = UINT64_MAX, window_off = UINT64_MAX;
static bool counting = true;

static void on_block_entered(unsigned int vcpu_index, void *userdata)
{
    struct block *b = userdata;
    (void)vcpu_index;
    if (b->start == window_on) {
        counting = true;
    } else if (b->start == window_off) {
        counting = false;
        last_entered = NULL;
    }
    if (!counting) {
        return;
    }
    b->execs++;
    if (last_entered != NULL && last_entered->fallthrough != b->start) {
        last_entered->taken++;
    }
    last_entered = b;
}

static void on_translation(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
    size_t n = qemu_plugin_tb_n_insns(tb);
    struct block *b;
    (void)id;
    if (n == 0) {
        return;
    }
    b = calloc(1, sizeof(*b) + n * sizeof(struct insn));
    if (b == NULL) {
        fputs("insn-profile: out of memory, block not counted\n", stderr);
        return;
    }
    b->n = n;
    for (size_t k = 0; k < n; k++) {
        struct qemu_plugin_insn *insn = qemu_plugin_tb_get_insn(tb, k);
        size_t size = qemu_plugin_insn_size(insn);
        const uint8_t *bytes = qemu_plugin_insn_data(insn);
        uint32_t enc = 0;
        for (size_t i = 0; i < size && i < 4; i++) {
            enc |= (uint32_t)bytes[i] << (8 * i);
        }
        /*
         * At the end of a guest page QEMU's Thumb decoder reads the next
         * halfword too, to see whether a 32-bit instruction crosses the
         * page, and reports those 4 bytes as the instruction. A Thumb
         * instruction is 32-bit only when its first halfword starts with
         * 0b11101, 0b11110 or 0b11111.
         */
        if (size == 4 && (enc & 0xFFFF) >> 11 < 0x1D) {
            size = 2;
            enc &= 0xFFFF;
        }
        b->insns[k].pc = qemu_plugin_insn_vaddr(insn);
        b->insns[k].size = (uint32_t)size;
        b->insns[k].encoding = enc;
    }
    b->start = b->insns[0].pc;
    b->fallthrough = b->insns[n - 1].pc + b->insns[n - 1].size;
    b->next_translated = all_blocks;
    all_blocks = b;
    qemu_plugin_register_vcpu_tb_exec_cb(tb, on_block_entered,
                                         QEMU_PLUGIN_CB_NO_REGS, b);
}

static void write_report(qemu_plugin_id_t id, void *userdata)
{
    FILE *f = fopen(out_path, "w");
    uint64_t total = 0;
    char msg[256];
    (void)id;
    (void)userdata;
    if (f == NULL) {
        snprintf(msg, sizeof(msg), "insn-profile: cannot write %s\n", out_path);
        fputs(msg, stderr);
        return;
    }
    for (struct block *b = all_blocks; b != NULL; b = b->next_translated) {
        if (b->execs == 0) {
            continue;
        }
        for (size_t k = 0; k < b->n; k++) {
            const struct insn *i = &b->insns[k];
            uint64_t taken = k + 1 == b->n ? b->taken : 0;
            fprintf(f, "%" PRIx64 " %u %x %" PRIu64 " %" PRIu64 "\n", i->pc,
                    i->size, i->encoding, b->execs, taken);
            total += b->execs;
        }
    }
    fclose(f);
    snprintf(msg, sizeof(msg),
             "insn-profile: %" PRIu64 " instructions counted, written to %s\n",
             total, out_path);
    fputs(msg, stderr);
}

EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info,
                               int argc, char **argv)
{
    (void)info;
    for (int k = 0; k < argc; k++) {
        if (strncmp(argv[k], "out=", 4) == 0) {
            out_path = argv[k] + 4;
        } else if (strncmp(argv[k], "on=", 3) == 0) {
            window_on = strtoull(argv[k] + 3, NULL, 16);
            counting = false;
        } else if (strncmp(argv[k], "off=", 4) == 0) {
            window_off = strtoull(argv[k] + 4, NULL, 16);
        } else {
            char msg[256];
            snprintf(msg, sizeof(msg), "insn-profile: unknown argument %s\n",
                     argv[k]);
            fputs(msg, stderr);
            return 1;
        }
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, on_translation);
    qemu_plugin_register_atexit_cb(id, write_report, NULL);
    return 0;
}

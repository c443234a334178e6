// SPDX-License-Identifier: MIT
// acore_coef_bank: safe coefficient updates for either top (rtl/acore_top.v, rtl/acore_serial_top.v)
// through its raw host port: a shadow bank the host writes at any time, a commit that replaces the
// active words only between samples and only when the shadow's CRC-32 is right, a generation tag
// for the outputs, and the background scrubber (rtl/acore_coef_scrub.v) that checks the active words.
//
// Commit (commit_i, one clock; ignored while busy_o):
//   REQ     one clock: the request registered.                           busy_o (and the shell gates
//   INIT    one clock: the CRC engine restarts.                          in_ready) from here on
//   CHECK   the shadow's words, 0..WORDS-1, through the CRC engine
//           (32/CRC_W clocks a word) while the samples in flight drain: the shell takes no new sample
//           and counts accepted - emitted (accept_i, emit_i), so the tops need no new port. Both done:
//           check_i and CRC != CRC_EXPECTED's word -> refused: the active words stay, refused_o, done_o;
//           otherwise:
//   STREAM  the shadow's words into the top's register file through its host write port, one a clock
//           (the shadow's output register drives the port's data);
//   SETTLE  SETTLE clocks for the last write to land (acore_top registers its port), then the tag
//           (bank_o) flips, the image's CRC becomes the scrubber's reference, done_o, busy_o falls.
//
//   commit_i   _/‾\_________________________________________________________
//   busy_o     ___/‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾\_____
//   state         |R|I| CHECK: CRC pass || drain (max of both) | STREAM WORDS |SETTLE|
//   top_we_o   ___________________________________________/‾‾‾‾‾‾‾‾‾‾‾‾‾‾\______
//   bank_o     ‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾‾\_____   (new tag)
//
// No sample is in flight while the words change, so every output was computed with exactly one
// image, the one its tag (bank_o when it leaves) names. Busy time from the clock of commit_i:
// max(6 + P + WORDS 32/CRC_W, drain) + WORDS + 2 + SETTLE clocks (P = 2 when CRC_W >= 16: the
// engine registers the word and splits the CRC's fold over two clocks; else 0; drain = clocks
// until the one after the last accepted sample has left the top; tb/shell/test_apb_shell.cpp
// checks this form).
//
// The top's host port belongs to the commit while it streams and to the scrubber otherwise; the
// host never drives it (the shell's register map has no window on the active words). The shadow's
// read port belongs to the commit while busy_o, to the register block otherwise, and to the
// register block's reads of the CRC registers always.
//
// CRC_SHADOW, CRC_SCRUB, CRC_REF and CRC_EXPECTED live in the shadow's block RAM, in the four
// words after the image (WORDS .. WORDS + 3; the RAM is 32 bits wide, which costs no block RAM
// where two 16-bit ones hold an 18-bit word): no flops, no read multiplexer of their own.
// CRC_EXPECTED is the register block's to write (exp_we_i, in an APB access phase, refused while
// busy_o); reset writes its reset value (EXP_RESET) into its word. The CHECK pass's end reads it
// (with CRC_SHADOW's write: another word) and the comparator takes it the clock after, so a
// checked commit compares with the word, which no write changes until the commit ends. The
// register block reads them in the setup phase like a COEF word (crc_*_re_i, exp_re_i), also
// while busy: the commit's shadow read of that clock waits one clock (the CRC engine keeps the
// word it folds, so only the read itself moves), and a CRC word is never read and written in one
// clock outside reset (CRC_EXPECTED's is written in an access phase, read in a setup phase or,
// while writes of it are refused, at the CHECK pass's end): CRC_SHADOW is written when the CHECK
// pass's CRC is ready and no CRC read is under way (the engine holds its CRC), CRC_REF when a
// commit is applied (a clock later after a CRC read: the engine still holds the CRC then),
// CRC_SCRUB when a scrubber pass ends; the pass's end waits for a clock without an APB setup
// phase or shadow or CRC_EXPECTED write, because it also reads CRC_REF's word for the scrubber's
// comparison (the RAM's output register holds it the clock after). Until its first write after
// reset an RO CRC word reads 0 (crc_*_zero_o; CRC_REF's: no commit applied yet).
`resetall
`default_nettype none

module acore_coef_bank #(
  parameter integer REG_W = 18,
  // Coefficient words of the top.
  parameter integer WORDS = 52,
  // Clocks from the top's host address to its reg_rdata_o.
  parameter integer RD_LAT = 2,
  // 1: the top's read-back stays while its address does (acore_top); 0: valid only in the clock
  // it is served (the serial core). The scrubber copies the word only with 0.
  parameter integer RD_HOLD = 0,
  // CRC bits per clock (rtl/acore_crc32.v).
  parameter integer CRC_W = 8,
  // Width of the in-flight sample counter: must hold the most samples the top holds at once.
  parameter integer CNT_W = 8,
  // Clocks after the last host write before samples flow again.
  parameter integer SETTLE = 2,
  // $readmemh image: the shadow's power-up contents (the shell gives the top the same one).
  parameter INIT_FILE = "",
  // CRC_EXPECTED's reset value (the register table's), written into its word in reset.
  parameter [31:0] EXP_RESET = 32'd0,
  // Derived, do not override.
  parameter integer ADDR_W = $clog2(WORDS)
) (
  input  wire              clk_i,
  input  wire              rst_i,
  // Shadow bank, register block side: write, and read (q one clock after sh_re_i) while !busy_o;
  // the CRC registers' words read (q one clock later, any time), and whether they hold a value.
  // The write data is PWDATA, the shadow's (its REG_W low bits) and CRC_EXPECTED's (exp_we_i).
  input  wire              sh_we_i,
  input  wire [ADDR_W-1:0] sh_waddr_i,
  input  wire [31:0]       sh_wdata_i,
  input  wire              sh_re_i,
  input  wire [ADDR_W-1:0] sh_raddr_i,
  input  wire              crc_shadow_re_i,
  input  wire              crc_scrub_re_i,
  input  wire              crc_ref_re_i,
  input  wire              exp_re_i,
  input  wire              exp_we_i,
  output wire [31:0]       sh_rdata_o,
  output wire              crc_shadow_zero_o,
  output wire              crc_scrub_zero_o,
  output wire              crc_ref_zero_o,
  // Control: commit request (one clock), CRC check and scrubbing enables.
  input  wire              commit_i,
  input  wire              check_i,
  input  wire              scrub_i,
  // A sample entered the top / a result left it (handshakes at the top's ports).
  input  wire              accept_i,
  input  wire              emit_i,
  // Live state.
  output wire              busy_o,
  output wire              bank_o,
  output wire              ref_valid_o,
  // Judged scrubber passes (wrapping; moves with the pass's verdict).
  output reg  [15:0]       scrub_passes_o,
  // Events, one clock each: a commit ended (applied or refused); it was refused (CRC); a scrub
  // pass found the active words changed.
  output wire              done_o,
  output wire              refused_o,
  output wire              scrub_err_o,
  // The top's raw host port (the write data is the shadow RAM's output register).
  output reg  [ADDR_W-1:0] top_addr_o,
  output wire [REG_W-1:0]  top_wdata_o,
  output wire              top_we_o,
  input  wire [REG_W-1:0]  top_rdata_i,
  // The top serves a host read given in this clock (acore_top: 1; serial core: in_ready_o).
  input  wire              top_rd_ok_i
);

  // Parameter rules (rtl/acore_check.v: they stop Verilator, Icarus and Yosys).
  acore_check #(.OK(WORDS >= 2), .VALUE(WORDS),
    .MSG("illegal parameter: WORDS must be at least 2"))
    WORDS_must_be_at_least_2 ();
  acore_check #(.OK(ADDR_W == $clog2(WORDS)), .VALUE(ADDR_W),
    .MSG("illegal parameter: ADDR_W is derived (clog2(WORDS)), do not override"))
    ADDR_W_is_derived ();
  acore_check #(.OK(REG_W >= 2 && REG_W <= 32), .VALUE(REG_W),
    .MSG("illegal parameter: REG_W must be 2..32"))
    REG_W_must_be_2_to_32 ();
  acore_check #(.OK(SETTLE >= 1 && SETTLE <= 15), .VALUE(SETTLE),
    .MSG("illegal parameter: SETTLE must be 1..15"))
    SETTLE_must_be_1_to_15 ();

  localparam [2:0] C_IDLE = 3'd0, C_INIT = 3'd1, C_CHECK = 3'd2, C_STREAM = 3'd3, C_SETTLE = 3'd4;
  // SETTLE's counter: SETTLE - 1 .. 0.
  localparam integer ST_W = (SETTLE > 1) ? $clog2(SETTLE) : 1;
  localparam integer SETTLE_LAST_I = SETTLE - 1;
  localparam [ST_W-1:0] SETTLE_LAST = SETTLE_LAST_I[ST_W-1:0];
  // The CHECK pass reads a shadow word every STEPS clocks, the CRC engine's pace, so the engine is
  // always ready for it and the feed needs no handshake (every control below is a flop or a gate
  // from flops).
  localparam integer STEPS = 32 / CRC_W;
  localparam integer SC_W = (STEPS > 1) ? $clog2(STEPS) : 1;
  localparam [SC_W-1:0] SC_LAST = STEPS[SC_W-1:0] - 1'b1;

  // state_q, and busy_q = (state_q != C_IDLE) as a flop: it selects the RAM's and the engine's inputs.
  // req_q: the commit request, registered (it comes from the APB write decode); busy_o covers it.
  reg [2:0] state_q;
  reg busy_q, req_q;
  assign busy_o = busy_q | req_q;
  always @(posedge clk_i) begin
    if (rst_i) req_q <= 1'b0;
    else req_q <= commit_i & ~busy_q & ~req_q;
  end

  // ---- shadow bank ----
  // ra_q: the next word the commit reads (the scrubber's address counter, which the commit clears
  // (c_clr) and counts on (c_re) while the scrubber stops: one counter, and no multiplexer on the
  // top's address; ra_last: it holds the last word); more_q: words left to read; sc_q: clocks to
  // the next read of the CHECK pass; ld_q: the RAM output holds the word read last clock (CHECK:
  // for the CRC engine); pend_q: the same in STREAM (for the top). x_rd: the register block reads
  // a CRC word in this clock (it has the read port: the commit's read waits).
  localparam integer RAM_AW = $clog2(WORDS + 4);
  localparam integer A_SHADOW_I = WORDS, A_SCRUB_I = WORDS + 1, A_REF_I = WORDS + 2;
  localparam integer A_EXP_I = WORDS + 3;
  localparam [RAM_AW-1:0] A_SHADOW = A_SHADOW_I[RAM_AW-1:0], A_SCRUB = A_SCRUB_I[RAM_AW-1:0];
  localparam [RAM_AW-1:0] A_REF = A_REF_I[RAM_AW-1:0], A_EXP = A_EXP_I[RAM_AW-1:0];
  wire [ADDR_W-1:0] ra_q;
  wire ra_last;
  reg more_q, ld_q, pend_q;
  reg [SC_W-1:0] sc_q;
  wire [31:0] q;
  wire x_rd = crc_shadow_re_i | crc_scrub_re_i | crc_ref_re_i | exp_re_i;
  wire c_re = more_q & ~x_rd &
      ((state_q == C_STREAM) | ((state_q == C_CHECK) & (sc_q == {SC_W{1'b0}})));
  wire crc_end, s_pass, ref_we, c_clr;
  wire crc_we = crc_end | s_pass | ref_we;
  wire [31:0] crc;
  // (reset writes CRC_EXPECTED's reset value; nothing else writes in reset)
  wire [31:0] ram_wdata = rst_i ? EXP_RESET : crc_we ? crc : sh_wdata_i;
  reg [RAM_AW-1:0] sh_waddr, sh_raddr;
  always @(*) begin
    sh_waddr = {RAM_AW{1'b0}};
    sh_waddr[ADDR_W-1:0] = sh_waddr_i;
    sh_raddr = {RAM_AW{1'b0}};
    sh_raddr[ADDR_W-1:0] = busy_q ? ra_q : sh_raddr_i;
  end
  // (the CHECK pass's end reads CRC_EXPECTED's word: crc_end; a pass's end CRC_REF's: s_pass)
  acore_sync_ram #(.W(32), .DEPTH(WORDS + 4), .INIT_WORDS(WORDS), .INIT_FILE(INIT_FILE)) u_shadow (
    .clk_i(clk_i), .we_i(rst_i | sh_we_i | exp_we_i | crc_we),
    .waddr_i((rst_i | exp_we_i) ? A_EXP :
             crc_we ? (crc_end ? A_SHADOW : s_pass ? A_SCRUB : A_REF) : sh_waddr),
    .wdata_i(ram_wdata), .re_i(x_rd | crc_end | s_pass | (busy_q ? c_re : sh_re_i)),
    .raddr_i(crc_shadow_re_i ? A_SHADOW : crc_scrub_re_i ? A_SCRUB : crc_ref_re_i ? A_REF :
             (exp_re_i | crc_end) ? A_EXP : s_pass ? A_REF : sh_raddr), .q_o(q));
  assign sh_rdata_o = q;

  // ---- CRC engine, the commit's while busy, the scrubber's otherwise ----
  wire crc_ready, crc_idle;
  wire s_init, s_load;
  wire [REG_W-1:0] s_word;
  // The engine takes the word in the clock of the load (the shadow's output register, the
  // scrubber's copy or (RD_HOLD) the top's read-back) and keeps what it still folds.
  acore_crc32 #(.CRC_W(CRC_W), .DATA_W(REG_W)) u_crc (
    .clk_i(clk_i), .rst_i(rst_i),
    .init_i(busy_q ? (state_q == C_INIT) : s_init),
    .load_i(busy_q ? ld_q : s_load),
    .word_i(busy_q ? q[REG_W-1:0] : s_word),
    .ready_o(crc_ready), .idle_o(crc_idle), .crc_o(crc));

  acore_coef_scrub #(.REG_W(REG_W), .WORDS(WORDS), .RD_LAT(RD_LAT), .HOLD(RD_HOLD)) u_scrub (
    .clk_i(clk_i), .rst_i(rst_i), .run_i(scrub_i & ~busy_q), .clr_i(c_clr), .inc_i(c_re),
    .last_o(ra_last), .addr_o(ra_q), .rdata_i(top_rdata_i),
    .rd_ok_i(top_rd_ok_i), .crc_init_o(s_init), .crc_load_o(s_load), .crc_word_o(s_word),
    .crc_ready_i(crc_ready), .crc_idle_i(crc_idle), .hold_i(sh_we_i | exp_we_i | sh_re_i),
    .pass_o(s_pass));

  // ---- samples in the top: accepted - emitted ----
  // One adder: + 1, - 1 (all ones) or + 0.
  reg [CNT_W-1:0] inflight_q;
  wire cnt_dn = emit_i & ~accept_i;
  always @(posedge clk_i) begin
    if (rst_i) inflight_q <= {CNT_W{1'b0}};
    else inflight_q <= inflight_q + {{(CNT_W-1){cnt_dn}}, accept_i ^ emit_i};
  end
  wire drained = (inflight_q == {CNT_W{1'b0}});

  // ---- the commit ----
  // One 32-bit comparator of the CRC with the RAM's output, registered (neq_q) in the clock the
  // output holds its user's reference: the commit's CRC_EXPECTED word the clock after the CHECK
  // pass's end (exp_ld_q), the scrubber's CRC_REF word the clock after a pass's end (pass1_q,
  // below); neq_q then holds until the next. sel_q records whether a commit was busy in the
  // clock of the last comparison (1: the commit's). The CRC stays still for the clocks its users
  // read neq_q.
  // The comparison in two levels, two bit pairs a LUT and an OR of the 16 (kept: left to itself
  // the LUT mapper spends about a LUT a bit on the 32-bit inequality).
  reg neq_q, sel_q, exp_ld_q, pass1_q;
  (* keep *) wire [15:0] ne2;
  genvar gi;
  generate
    for (gi = 0; gi < 16; gi = gi + 1) begin : g_ne
      assign ne2[gi] = |(crc[2*gi +: 2] ^ q[2*gi +: 2]);
    end
  endgenerate
  always @(posedge clk_i) begin
    if (busy_q ? exp_ld_q : pass1_q) neq_q <= |ne2;
    sel_q <= busy_q;
  end

  // fed: the last shadow word went into the CRC engine (no word left to read, none loading);
  // crc_done: its CRC is in CRC_SHADOW's word (written in a clock without a CRC read, which
  // also reads CRC_EXPECTED's; the engine keeps the CRC until the commit ends): the clock after
  // (exp_ld_q) and from then on; cmp_q: neq_q holds its comparison with CRC_EXPECTED (the clock
  // after exp_ld_q and from then on). Both are gates of flops the sequence has anyway.
  reg cmp_q, bank_q, ref_valid_q;
  reg [ST_W-1:0] settle_q;
  wire fed = ~more_q & ~ld_q;
  wire crc_done = cmp_q | exp_ld_q;
  assign crc_end = (state_q == C_CHECK) & fed & ~crc_done & crc_idle & ~x_rd;
  wire decide = (state_q == C_CHECK) & cmp_q & drained;
  wire refuse = decide & check_i & neq_q;
  wire apply = (state_q == C_SETTLE) & (settle_q == {ST_W{1'b0}});
  // The sequence's state, reset; its counters and flags below are set on the way into the state
  // that reads them (INIT, the decision, STREAM's end), so they need no reset (nor a reset term in
  // their enables).
  always @(posedge clk_i) begin
    if (rst_i) begin
      state_q <= C_IDLE;
      busy_q <= 1'b0;
      bank_q <= 1'b0;
      ref_valid_q <= 1'b0;
      pend_q <= 1'b0;
      ld_q <= 1'b0;
      exp_ld_q <= 1'b0;
    end else begin
      pend_q <= (state_q == C_STREAM) & c_re;
      ld_q <= (state_q == C_CHECK) & c_re;
      exp_ld_q <= crc_end;
      case (state_q)
        C_IDLE: begin
          if (req_q) begin
            state_q <= C_INIT;
            busy_q <= 1'b1;
          end
        end
        C_INIT: state_q <= C_CHECK;
        C_CHECK: begin
          if (decide) begin
            state_q <= refuse ? C_IDLE : C_STREAM;
            busy_q <= ~refuse;
          end
        end
        C_STREAM: if (!more_q && !pend_q) state_q <= C_SETTLE;
        default: begin  // C_SETTLE
          if (apply) begin
            bank_q <= ~bank_q;
            ref_valid_q <= 1'b1;
            state_q <= C_IDLE;
            busy_q <= 1'b0;
          end
        end
      endcase
    end
  end
  assign c_clr = (state_q == C_INIT) | decide;
  always @(posedge clk_i) begin
    if (c_clr) more_q <= 1'b1;
    else if (c_re) more_q <= ~ra_last;
    if (state_q == C_INIT) sc_q <= {SC_W{1'b0}};
    else if (c_re) sc_q <= SC_LAST;
    else if (sc_q != {SC_W{1'b0}}) sc_q <= sc_q - 1'b1;
    cmp_q <= (state_q == C_CHECK) & crc_done;
    settle_q <= (state_q == C_STREAM) ? SETTLE_LAST : settle_q - 1'b1;
  end
  // The CRC registers read 0 until the first commit (and pass): sh_zero_q and sc_zero_q, kept as
  // the ports want them (set in reset, cleared by the first write). An applied commit's CRC is the
  // engine's still (it folds nothing from the CHECK pass's end to the commit's).
  // ref_pend_q: CRC_REF's word waits a clock (its apply met a CRC read); the APB's next setup
  // phase is a clock later still.
  reg sh_zero_q, sc_zero_q, ref_pend_q;
  always @(posedge clk_i) begin
    if (rst_i) begin
      sh_zero_q <= 1'b1;
      sc_zero_q <= 1'b1;
      ref_pend_q <= 1'b0;
    end else begin
      if (crc_end) sh_zero_q <= 1'b0;
      if (s_pass) sc_zero_q <= 1'b0;
      ref_pend_q <= apply & x_rd;
    end
  end
  assign ref_we = (apply & ~x_rd) | ref_pend_q;
  assign crc_shadow_zero_o = sh_zero_q;
  assign crc_scrub_zero_o = sc_zero_q;
  assign crc_ref_zero_o = ~ref_valid_q;
  // The top's port: the address counter's last value: in STREAM the word read last clock (its
  // data the shadow's output register), else the scrubber's address. (After a commit it holds
  // where the commit left the counter until a scrubber pass starts: a read that nothing takes, of
  // a word or past the last, which the tops answer with 0.)
  always @(posedge clk_i) top_addr_o <= ra_q;
  assign top_we_o = pend_q;
  assign top_wdata_o = q[REG_W-1:0];

  // ---- scrubber passes ----
  // The comparison of the clock after the pass is read two clocks after it (the flag three); a
  // commit starting meanwhile takes the comparator, and that pass goes unjudged.
  reg pass2_q, judged_q, scrub_bad;
  always @(posedge clk_i) begin
    if (rst_i) begin
      pass1_q <= 1'b0;
      pass2_q <= 1'b0;
      judged_q <= 1'b0;
      scrub_bad <= 1'b0;
    end else begin
      pass1_q <= s_pass;
      pass2_q <= pass1_q;
      judged_q <= pass2_q & ~sel_q;
      scrub_bad <= pass2_q & ~sel_q & ref_valid_q & neq_q;
    end
  end
  // CRC_SCRUB's word takes the pass's CRC when it ends (above); the pass counter moves in the clock
  // the verdict reaches STATUS (scrub_err_o is registered there), so a host that sees it move sees
  // the verdict.
  always @(posedge clk_i) begin
    if (rst_i) scrub_passes_o <= 16'd0;
    else if (judged_q) scrub_passes_o <= scrub_passes_o + 16'd1;
  end

  assign bank_o = bank_q;
  assign ref_valid_o = ref_valid_q;
  assign done_o = apply | refuse;
  assign refused_o = refuse;
  assign scrub_err_o = scrub_bad;

endmodule

`resetall

// SPDX-License-Identifier: MIT
// acore_spi_as5047: an SPI slave that answers the AS5047P's frame, so a drive's existing AS5047P
// driver (SimpleFOC's MagneticSensorSPI, ODrive's SPI_ABS_AMS mode, ...) reads AngleCore's angle
// unchanged.
//
// The frame (AS5047P datasheet, SPI interface): mode 1 (CPOL = 0, CPHA = 1: the master changes
// MOSI on SCLK's rising edge and samples MISO on its falling edge), 16 bits MSB first, CSn low for
// the frame. A command is {PAR, R/W, ADDR[13:0]}: PAR makes the 16 bits' parity even, R/W = 1 reads.
// The answer to a read comes in the next frame, as {PAR, EF, DATA[13:0]} with even parity. The
// registers:
//   0x0000 NOP       0
//   0x0001 ERRFL     bit 2 PARERR, bit 1 INVCOMM, bit 0 FRERR; cleared by its own read
//   0x3FFC DIAAGC    bit 11 MAGL (los_i), bit 10 MAGH (dos_i), bit 9 COF (ovf_i), bit 8 LF
//                    (~lot_i: the angle is settled), bits 7:0 AGC (agc_i)
//   0x3FFD MAG       mag_i
//   0x3FFE ANGLEUNC  the uncompensated angle's upper 14 bits
//   0x3FFF ANGLECOM  the compensated angle's upper 14 bits
// Errors: a frame whose parity is odd sets PARERR and is ignored; a frame that is not 16 clocks
// long, or follows a CSn gap shorter than 2 clocks (below), sets FRERR and is ignored; a read of another address, or a write command (this port has no
// writable register; the data frame that follows it is consumed), sets INVCOMM. NOP, address 0,
// is no command whether R/W is set or not (0x0000 is the frame drivers send to collect an answer). EF, bit 14 of every
// answer, is high while ERRFL holds an error, so the answer after a refused frame carries it (its
// data is then NOP's 0), until ERRFL is read.
//
// One clock domain: SCLK, CSn and MOSI are oversampled through SYNC flops each. MOSI is taken at
// the synchronized falling edge, the same stage as SCLK's, so it is the value the master held
// across that edge. The next MISO bit is presented SYNC + 1 clocks after each falling edge (so the
// master's hold is met) and is stable until SYNC + 1 clocks after the next one: the master samples
// it right when the SCLK period is at least SYNC + 2 clocks (one clock of set-up). That is the
// port's timing rule, and SCLK_MIN, the shortest SCLK period (in clocks) the port is built for,
// must meet it: SCLK_MIN >= SYNC + 2, refused at elaboration otherwise (SYNC = 2 takes SCLK up to
// clk/4, SYNC = 3 clk/5, SYNC = 4 clk/6). The answer word follows its register while CSn is high
// and freezes when CSn falls (the angle is the one at the start of the frame that carries it).
// CSn timing, in clocks of clk_i: the first falling SCLK edge at least SYNC + 2 clocks after CSn
// falls (the AS5047P's own t_L, 350 ns, is longer above 12 MHz); CSn high at least 2 clocks
// between frames (the answer is loaded in the second). A frame after a shorter gap is a framing
// error, detected: its answer is {PAR, EF, 0} (0xC000), its command is ignored, FRERR is set.
`resetall
`default_nettype none

module acore_spi_as5047 #(
  // Bits of the angle inputs (at least the 14 the frame carries: their upper 14 bits are sent).
  parameter integer ANGLE_W = 16,
  // Synchronizer flops on SCLK, CSn and MOSI.
  parameter integer SYNC = 2,
  // The shortest SCLK period the port is built for, in clocks of clk_i: at least SYNC + 2.
  parameter integer SCLK_MIN = 4
) (
  input  wire               clk_i,
  input  wire               rst_i,
  // The SPI pins (asynchronous to clk_i). MISO is driven while miso_oe_o (CSn low).
  input  wire               sclk_i,
  input  wire               csn_i,
  input  wire               mosi_i,
  output wire               miso_o,
  output wire               miso_oe_o,
  // What the registers read.
  input  wire [ANGLE_W-1:0] angle_unc_i,
  input  wire [ANGLE_W-1:0] angle_com_i,
  input  wire [13:0]        mag_i,
  input  wire [7:0]         agc_i,
  input  wire               los_i,
  input  wire               dos_i,
  input  wire               ovf_i,
  input  wire               lot_i,
  // A pulse at the end of each frame, and ERRFL (for status and tests).
  output reg                frame_o,
  output wire [2:0]         errfl_o
);

  acore_check #(.OK(ANGLE_W >= 14 && ANGLE_W <= 32), .VALUE(ANGLE_W),
    .MSG("illegal parameter: ANGLE_W must be 14..32 (the frame carries 14 bits)")) ANGLE_W_must_be_14_to_32 ();
  acore_check #(.OK(SYNC >= 2 && SYNC <= 4), .VALUE(SYNC),
    .MSG("illegal parameter: SYNC must be 2..4")) SYNC_must_be_2_to_4 ();
  acore_check #(.OK(SCLK_MIN >= SYNC + 2), .VALUE(SCLK_MIN),
    .MSG("illegal parameter: SCLK_MIN must be >= SYNC + 2 (MISO moves SYNC + 1 clocks after SCLK falls)"))
    SCLK_MIN_must_be_at_least_SYNC_plus_2 ();

  localparam [13:0] A_NOP = 14'h0000, A_ERRFL = 14'h0001, A_DIAAGC = 14'h3FFC, A_MAG = 14'h3FFD,
                    A_ANGLEUNC = 14'h3FFE, A_ANGLECOM = 14'h3FFF;

  // ---- synchronizers (idle: SCLK low, CSn high) and edges ----
  // (CSn one stage longer: a falling edge sees whether CSn was high for two clocks before it.)
  reg [SYNC:0] sclk_s;
  reg [SYNC+1:0] csn_s;
  reg [SYNC-1:0] mosi_s;
  always @(posedge clk_i) begin
    if (rst_i) begin
      sclk_s <= {(SYNC+1){1'b0}};
      csn_s <= {(SYNC+2){1'b1}};
      mosi_s <= {SYNC{1'b0}};
    end else begin
      sclk_s <= {sclk_s[SYNC-1:0], sclk_i};
      csn_s <= {csn_s[SYNC:0], csn_i};
      mosi_s <= {mosi_s[SYNC-2:0], mosi_i};
    end
  end
  wire sel = ~csn_s[SYNC-1];
  wire fall = sel & sclk_s[SYNC] & ~sclk_s[SYNC-1];
  wire mosi = mosi_s[SYNC-1];
  wire cs_fall = csn_s[SYNC] & ~csn_s[SYNC-1];
  wire cs_rise = ~csn_s[SYNC] & csn_s[SYNC-1];
  // CSn was high for one clock only: the answer of the frame before was not loaded.
  wire cs_short = cs_fall & ~csn_s[SYNC+1];

  // ---- the answer of the next frame ----
  reg [2:0] errfl_q;   // {PARERR, INVCOMM, FRERR}
  reg [2:0] ans_q;     // which register: 0 NOP, 1 ERRFL, 4 DIAAGC, 5 MAG, 6 ANGLEUNC, 7 ANGLECOM
  reg [13:0] data;
  always @(*) begin
    case (ans_q)
      3'd1: data = {11'd0, errfl_q};
      3'd4: data = {2'b00, los_i, dos_i, ovf_i, ~lot_i, agc_i};
      3'd5: data = mag_i;
      3'd6: data = angle_unc_i[ANGLE_W-1 -: 14];
      3'd7: data = angle_com_i[ANGLE_W-1 -: 14];
      default: data = 14'd0;
    endcase
  end
  wire ef = |errfl_q;
  wire [15:0] answer = {^{ef, data}, ef, data};

  // ---- the frame ----
  reg [15:0] rx_q, tx_q;
  reg [4:0] bits_q;    // saturates at 17: too long
  reg wr_data_q;       // the next frame is a write's data frame
  reg short_q;         // this frame followed a CSn gap of one clock: a framing error
  wire parity_ok = ~^rx_q;
  wire read = rx_q[14];
  wire [13:0] addr = rx_q[13:0];
  wire known = (addr == A_NOP) | (addr == A_ERRFL) | (addr == A_DIAAGC) | (addr == A_MAG) |
               (addr == A_ANGLEUNC) | (addr == A_ANGLECOM);
  // Errors found at the end of this frame, as ERRFL bits.
  // NOP (address 0) is no command either way: the frame drivers send to collect an answer is 0x0000.
  wire nop = (addr == A_NOP);
  wire write = ~read & ~nop;
  wire [2:0] err_new = (bits_q != 5'd16 || short_q) ? 3'b001 : ~parity_ok ? 3'b100 :
                       wr_data_q ? 3'b000 : (write | ~known) ? 3'b010 : 3'b000;
  wire cmd_ok = cs_rise & (bits_q == 5'd16) & ~short_q & parity_ok & ~wr_data_q;
  // ERRFL's own answer clears it when the frame carrying it starts (not after a short gap: the
  // frame then carries 0xC000 instead).
  wire clear_errfl = cs_fall & (ans_q == 3'd1) & ~cs_short;
  always @(posedge clk_i) begin
    if (rst_i) begin
      errfl_q <= 3'd0;
      ans_q <= 3'd0;
      bits_q <= 5'd0;
      wr_data_q <= 1'b0;
      short_q <= 1'b0;
      frame_o <= 1'b0;
      tx_q <= 16'd0;
    end else begin
      frame_o <= cs_rise;
      if (!sel) tx_q <= answer;
      else if (cs_short) tx_q <= 16'hC000;  // EF with even parity, data 0
      else if (fall) tx_q <= {tx_q[14:0], 1'b0};
      if (cs_fall) short_q <= cs_short;
      if (cs_fall) bits_q <= 5'd0;
      else if (fall && bits_q != 5'd17) bits_q <= bits_q + 5'd1;
      errfl_q <= (clear_errfl ? 3'd0 : errfl_q) | (cs_rise ? err_new : 3'd0);
      if (cs_rise) begin
        if (cmd_ok) begin
          wr_data_q <= write;
          ans_q <= ~read ? 3'd0 : (addr == A_ERRFL) ? 3'd1 : (addr == A_DIAAGC) ? 3'd4 :
                   (addr == A_MAG) ? 3'd5 : (addr == A_ANGLEUNC) ? 3'd6 : (addr == A_ANGLECOM) ? 3'd7 : 3'd0;
        end else begin
          // A refused frame (or a write's data frame): the next answer is NOP's.
          if (bits_q == 5'd16) wr_data_q <= 1'b0;
          ans_q <= 3'd0;
        end
      end
    end
    if (fall) rx_q <= {rx_q[14:0], mosi};
  end
  assign miso_o = tx_q[15];
  assign miso_oe_o = ~csn_s[SYNC-1];
  assign errfl_o = errfl_q;

endmodule

`resetall

// Histogram memory of one tof-spad TDC group: one bin per (column, code), incremented by the
// TDC's events during a row integration, then read out word by word (read-and-clear, so the
// next row starts from zero) with each column's peak and centroid sums.
// Reference: the events[column][code] of systemc/tof_spad/sensor_kernel.h (GroupHistogram);
// peak = first code of the largest count; centroid = num / den with num = sum code x count,
// den = sum count over the column's codes.
//
// After reset the memory (random at power-up) is swept to zero (busy_o high, CPT x CODES_MAX
// cycles). Readout: read_i starts it; every word takes cycles_per_word_i cycles, word_valid_o
// in its first cycle with word_column_o / word_code_o / word_o; peak_valid_o pulses in the
// cycle after a column's last word with its results. Counts saturate (saturated_o, sticky until
// the next readout starts) instead of wrapping.
module tdc_histogram #(
    parameter int CPT        = 4,     // columns of the group
    parameter int COL_BITS   = 2,     // column index width
    parameter int BIN_BITS   = 11,    // code width
    parameter int CODES_MAX  = 1024,  // memory words per column
    parameter int COUNT_BITS = 16,    // bin counter width
    parameter int SUM_BITS   = 40     // centroid numerator width
) (
    input  logic                  clk,
    input  logic                  rst,
    input  logic                  event_i,             // TDC event (code < codes)
    input  logic [  COL_BITS-1:0] event_column_i,
    input  logic [  BIN_BITS-1:0] event_code_i,
    input  logic                  read_i,              // start the readout (when idle)
    input  logic [  BIN_BITS-1:0] codes_i,             // codes per column (<= CODES_MAX)
    input  logic [           7:0] cycles_per_word_i,   // >= 1
    output logic                  busy_o,              // clearing or reading
    output logic                  word_valid_o,
    output logic [  COL_BITS-1:0] word_column_o,
    output logic [  BIN_BITS-1:0] word_code_o,
    output logic [COUNT_BITS-1:0] word_o,
    output logic                  peak_valid_o,
    output logic [  COL_BITS-1:0] peak_column_o,
    output logic [  BIN_BITS-1:0] peak_code_o,
    output logic [COUNT_BITS-1:0] peak_count_o,
    output logic [  SUM_BITS-1:0] centroid_num_o,
    output logic [          31:0] centroid_den_o,
    output logic                  saturated_o
);
  localparam int WORDS = CPT * CODES_MAX;
  localparam int ADDR_BITS = $clog2(WORDS);

  typedef enum logic [1:0] {
    S_CLEAR,
    S_IDLE,
    S_READ
  } state_t;
  state_t state_q;
  logic [COUNT_BITS-1:0] mem[WORDS];
  logic [ADDR_BITS-1:0] clr_q;
  logic [COL_BITS-1:0] col_q;
  logic [BIN_BITS-1:0] code_q;
  logic [7:0] w_q;
  logic [COUNT_BITS-1:0] max_q;
  logic [BIN_BITS-1:0] peak_q;
  logic [SUM_BITS-1:0] num_q;
  logic [31:0] den_q;
  logic sat_q, pv_q;
  logic [COL_BITS-1:0] pcol_q;
  logic [BIN_BITS-1:0] pcode_q;
  logic [COUNT_BITS-1:0] pcount_q;
  logic [SUM_BITS-1:0] pnum_q;
  logic [31:0] pden_q;

  wire [ADDR_BITS-1:0] ev_addr = ADDR_BITS'(event_column_i) * ADDR_BITS'(CODES_MAX) + ADDR_BITS'(event_code_i);
  wire [ADDR_BITS-1:0] rd_addr = ADDR_BITS'(col_q) * ADDR_BITS'(CODES_MAX) + ADDR_BITS'(code_q);
  wire [COUNT_BITS-1:0] ev_count = mem[ev_addr];
  wire [COUNT_BITS-1:0] word = mem[rd_addr];
  wire word_end = w_q == cycles_per_word_i - 1'b1;
  wire last_code = code_q == codes_i - 1'b1;
  wire last_col = col_q == COL_BITS'(CPT - 1);
  // The column's accumulators including the current word.
  wire first = code_q == '0;
  wire take = first || word > max_q;
  wire [COUNT_BITS-1:0] max_n = take ? word : max_q;
  wire [BIN_BITS-1:0] peak_n = take ? code_q : peak_q;
  wire [SUM_BITS-1:0] num_n = (first ? '0 : num_q) + SUM_BITS'(code_q) * SUM_BITS'(word);
  wire [31:0] den_n = (first ? '0 : den_q) + 32'(word);

  always_ff @(posedge clk) begin
    pv_q <= 1'b0;
    if (rst) begin
      state_q <= S_CLEAR;
      clr_q <= '0;
      sat_q <= 1'b0;
    end else begin
      case (state_q)
        S_CLEAR: begin
          mem[clr_q] <= '0;
          clr_q <= clr_q + 1'b1;
          if (clr_q == ADDR_BITS'(WORDS - 1)) state_q <= S_IDLE;
        end
        S_IDLE: begin
          col_q <= '0;
          code_q <= '0;
          w_q <= '0;
          if (event_i) begin
            if (&ev_count) sat_q <= 1'b1;  // saturate, never wrap
            else mem[ev_addr] <= ev_count + 1'b1;
          end
          if (read_i) begin
            state_q <= S_READ;
            sat_q <= 1'b0;
          end
        end
        default: begin  // S_READ
          w_q <= word_end ? '0 : w_q + 1'b1;
          if (word_end) begin
            mem[rd_addr] <= '0;
            max_q <= max_n;
            peak_q <= peak_n;
            num_q <= num_n;
            den_q <= den_n;
            code_q <= last_code ? '0 : code_q + 1'b1;
            if (last_code) begin
              pv_q <= 1'b1;
              pcol_q <= col_q;
              pcode_q <= peak_n;
              pcount_q <= max_n;
              pnum_q <= num_n;
              pden_q <= den_n;
              col_q <= col_q + 1'b1;
              if (last_col) state_q <= S_IDLE;
            end
          end
        end
      endcase
    end
  end

  assign busy_o = state_q != S_IDLE;
  assign word_valid_o = state_q == S_READ && w_q == '0;
  assign word_column_o = col_q;
  assign word_code_o = code_q;
  assign word_o = word;
  assign peak_valid_o = pv_q;
  assign peak_column_o = pcol_q;
  assign peak_code_o = pcode_q;
  assign peak_count_o = pcount_q;
  assign centroid_num_o = pnum_q;
  assign centroid_den_o = pden_q;
  assign saturated_o = sat_q;

  always @(posedge clk) begin
    if (!rst) begin
`ifdef __ICARUS__
      if (event_i && state_q != S_IDLE) $error("a_event_while_busy: event during clear/readout");
      if (event_i && event_code_i >= codes_i) $error("a_event_code_in_range: code >= codes");
`else
      a_event_while_busy : assert (!(event_i && state_q != S_IDLE))
      else $error("event during clear/readout (lost)");
      a_event_code_in_range : assert (!(event_i && event_code_i >= codes_i))
      else $error("event code >= codes");
`endif
    end
  end
endmodule

module not_a_block(input logic clk);
endmodule

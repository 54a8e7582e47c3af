module centre_processor(input logic clk
endmodule

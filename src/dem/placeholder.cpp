namespace veridem::dem {}

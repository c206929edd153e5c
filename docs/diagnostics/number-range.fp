!!ARBfp1.0
# 1e39 is beyond the largest float32: it becomes infinity
MOV result.color, {1e39, 0, 0, 1};
END

!!ARBfp1.0
# comments anywhere, tabs, blank lines, statements split over lines and sharing a line (ARBfp 3.11.2)
#
#	a comment with tabs and punctuation: !@$%^&*()[]{};:'",.<>/?\|`~
   # indented comment

TEMP	a,   # first
	b;   # second
MOV a,      # split after the comma
    fragment.color;  MOV b, fragment.color.secondary;   # two on one line
ADD
  result.color
  ,
  a
  ,
  b
  ;
# a comment right before END
END

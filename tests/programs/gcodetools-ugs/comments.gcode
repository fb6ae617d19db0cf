(first comment)
;second comment
G21 ;inline comment 1
G21 (inline comment 2)
G0 X10 Y10 Z10
; another comment
G0 X20 Y20 Z20
(another comment)
G0 X30 Y30 Z30

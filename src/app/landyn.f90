program landyn
  implicit none
  print '(a)', 'landyn: under construction'
end program landyn

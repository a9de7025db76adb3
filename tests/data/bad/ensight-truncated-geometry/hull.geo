hull geometry
second line
node id off
element id off
part
         1
hull
coordinates
         4
 0.0
 1.0

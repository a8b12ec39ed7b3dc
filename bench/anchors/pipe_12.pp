<!DOCTYPE PickedPoints>
<PickedPoints>
 <DocumentData>
  <DataFileName name="pipe.off"/>
  <templateName name=""/>
 </DocumentData>
 <point x="0.170625" y="-0.5" z="-1.40397e-007" active="1" name="bottom_inner_000"/>
 <point x="-0.0774619" y="-0.5" z="-0.152028" active="1" name="bottom_inner_120"/>
 <point x="-0.0774619" y="-0.5" z="0.152028" active="1" name="bottom_inner_240"/>
 <point x="0.096111" y="-0.5" z="-0.295799" active="1" name="bottom_outer_072"/>
 <point x="-0.311022" y="-0.5" z="-1.40397e-007" active="1" name="bottom_outer_180"/>
 <point x="0.0961111" y="-0.5" z="0.295799" active="1" name="bottom_outer_288"/>
 <point x="0.0774619" y="0.5" z="-0.152028" active="1" name="top_inner_060"/>
 <point x="-0.170625" y="0.5" z="-1.40397e-007" active="1" name="top_inner_180"/>
 <point x="0.0774619" y="0.5" z="0.152028" active="1" name="top_inner_300"/>
 <point x="0.311022" y="0.5" z="-1.40397e-007" active="1" name="top_outer_000"/>
 <point x="-0.096111" y="0.5" z="-0.295799" active="1" name="top_outer_108"/>
 <point x="-0.251622" y="0.5" z="0.182814" active="1" name="top_outer_216"/>
</PickedPoints>

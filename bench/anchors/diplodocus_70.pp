<!DOCTYPE PickedPoints>
<PickedPoints>
 <DocumentData>
  <DataFileName name="diplodocus.off"/>
  <templateName name=""/>
 </DocumentData>
 <point x="0.5" y="0.373614" z="0.102367" active="1" name="nose_tip"/>
 <point x="0.461273" y="0.370887" z="0.102598" active="1" name="chin"/>
 <point x="0.444185" y="0.467169" z="0.112683" active="1" name="head_top"/>
 <point x="0.428221" y="0.418858" z="0.0693726" active="1" name="left_cheek"/>
 <point x="0.421334" y="0.417971" z="0.152828" active="1" name="right_cheek"/>
 <point x="0.315926" y="0.411933" z="0.098183" active="1" name="nape"/>
 <point x="0.251419" y="0.20607" z="0.0804909" active="1" name="neck_mid"/>
 <point x="0.28536" y="-0.0844774" z="0.0130721" active="1" name="neck_bottom"/>
 <point x="0.143213" y="0.0548866" z="0.0397151" active="1" name="withers"/>
 <point x="-0.0304983" y="0.0501129" z="0.0403434" active="1" name="mid_back"/>
 <point x="-0.171206" y="0.0234907" z="-0.00820197" active="1" name="rump"/>
 <point x="-0.295879" y="-0.0540693" z="-0.0174046" active="1" name="tail_base"/>
 <point x="-0.498708" y="-0.344279" z="-0.015983" active="1" name="tail_tip"/>
 <point x="0.188609" y="-0.173303" z="0.000729217" active="1" name="chest"/>
 <point x="-0.0243493" y="-0.189921" z="0.0178663" active="1" name="belly"/>
 <point x="-0.0272867" y="-0.074737" z="-0.088538" active="1" name="left_flank"/>
 <point x="-0.0119251" y="-0.0746748" z="0.133519" active="1" name="right_flank"/>
 <point x="0.176686" y="-0.287908" z="-0.0645181" active="1" name="left_front_knee"/>
 <point x="0.199519" y="-0.321521" z="0.116827" active="1" name="right_front_knee"/>
 <point x="-0.186368" y="-0.255804" z="-0.106866" active="1" name="left_hind_knee"/>
 <point x="-0.0770937" y="-0.282281" z="0.0915344" active="1" name="right_hind_knee"/>
 <point x="0.217292" y="-0.417623" z="-0.076737" active="1" name="left_front_foot"/>
 <point x="0.263188" y="-0.456722" z="0.114765" active="1" name="right_front_foot"/>
 <point x="-0.211207" y="-0.361051" z="-0.116352" active="1" name="left_hind_foot"/>
 <point x="-0.0720354" y="-0.413111" z="0.0597658" active="1" name="right_hind_foot"/>
 <point x="0.474927" y="0.42733" z="0.0999954" active="1" name="nose_tip~head_top@50"/>
 <point x="0.483981" y="0.363326" z="0.100011" active="1" name="nose_tip~chin@50"/>
 <point x="0.466239" y="0.397046" z="0.0791256" active="1" name="nose_tip~left_cheek@50"/>
 <point x="0.462726" y="0.404739" z="0.136911" active="1" name="nose_tip~right_cheek@50"/>
 <point x="0.37159" y="0.454857" z="0.105005" active="1" name="head_top~nape@50"/>
 <point x="0.337866" y="0.298883" z="0.0874923" active="1" name="chin~neck_bottom@33"/>
 <point x="0.310236" y="0.106425" z="0.0574496" active="1" name="chin~neck_bottom@67"/>
 <point x="0.280405" y="0.308647" z="0.0865174" active="1" name="nape~neck_mid@50"/>
 <point x="0.218223" y="0.111198" z="0.0683533" active="1" name="neck_mid~withers@50"/>
 <point x="0.325711" y="0.286602" z="0.0704976" active="1" name="left_cheek~left_flank@25"/>
 <point x="0.244952" y="0.124234" z="0.0366269" active="1" name="left_cheek~left_flank@50"/>
 <point x="0.29815" y="0.309587" z="0.116944" active="1" name="right_cheek~right_flank@25"/>
 <point x="0.239787" y="0.14649" z="0.0821267" active="1" name="right_cheek~right_flank@50"/>
 <point x="0.0509107" y="0.0510691" z="0.0382568" active="1" name="withers~mid_back@50"/>
 <point x="-0.10985" y="0.0428685" z="0.0197552" active="1" name="mid_back~rump@50"/>
 <point x="-0.236763" y="-0.00950579" z="-0.0229324" active="1" name="rump~tail_base@50"/>
 <point x="-0.348924" y="-0.171095" z="-0.0103345" active="1" name="tail_base~tail_tip@33"/>
 <point x="-0.388607" y="-0.294805" z="-0.0174155" active="1" name="tail_base~tail_tip@67"/>
 <point x="0.249268" y="-0.136333" z="0.00601181" active="1" name="neck_bottom~chest@50"/>
 <point x="0.0847073" y="-0.193484" z="-0.00527715" active="1" name="chest~belly@50"/>
 <point x="-0.195732" y="-0.155632" z="-0.0253433" active="1" name="belly~tail_base@50"/>
 <point x="-0.029237" y="0.00614068" z="-0.0437715" active="1" name="left_flank~mid_back@50"/>
 <point x="-0.0274052" y="-0.000738853" z="0.111524" active="1" name="right_flank~mid_back@50"/>
 <point x="-0.0285431" y="-0.150165" z="-0.0559792" active="1" name="left_flank~belly@50"/>
 <point x="-0.0325116" y="-0.152453" z="0.0995128" active="1" name="right_flank~belly@50"/>
 <point x="-0.167248" y="-0.0475517" z="-0.100153" active="1" name="left_flank~tail_base@50"/>
 <point x="-0.185554" y="-0.032262" z="0.113983" active="1" name="right_flank~tail_base@50"/>
 <point x="0.21395" y="-0.176178" z="-0.0318542" active="1" name="neck_bottom~left_front_knee@50"/>
 <point x="0.220633" y="-0.180303" z="0.107307" active="1" name="neck_bottom~right_front_knee@50"/>
 <point x="0.159869" y="-0.0291632" z="-0.0664637" active="1" name="withers~left_front_knee@33"/>
 <point x="0.164409" y="-0.151744" z="-0.0870118" active="1" name="withers~left_front_knee@67"/>
 <point x="0.130315" y="-0.0422154" z="0.141955" active="1" name="withers~right_front_knee@33"/>
 <point x="0.167267" y="-0.184542" z="0.166247" active="1" name="withers~right_front_knee@67"/>
 <point x="-0.18587" y="-0.044917" z="-0.0932918" active="1" name="rump~left_hind_knee@33"/>
 <point x="-0.168425" y="-0.154875" z="-0.128176" active="1" name="rump~left_hind_knee@67"/>
 <point x="-0.211449" y="-0.0444279" z="0.0870608" active="1" name="rump~right_hind_knee@33"/>
 <point x="-0.168824" y="-0.179086" z="0.0872586" active="1" name="rump~right_hind_knee@67"/>
 <point x="0.168484" y="-0.364407" z="-0.0716698" active="1" name="left_front_knee~left_front_foot@50"/>
 <point x="0.214601" y="-0.400013" z="0.112729" active="1" name="right_front_knee~right_front_foot@50"/>
 <point x="-0.233367" y="-0.307407" z="-0.108885" active="1" name="left_hind_knee~left_hind_foot@50"/>
 <point x="-0.0990798" y="-0.352117" z="0.073867" active="1" name="right_hind_knee~right_hind_foot@50"/>
 <point x="0.183486" y="-0.227162" z="-0.03465" active="1" name="chest~left_front_knee@50"/>
 <point x="0.182607" y="-0.205674" z="0.105411" active="1" name="chest~right_front_knee@50"/>
 <point x="-0.119989" y="-0.152169" z="-0.0521949" active="1" name="belly~left_hind_knee@50"/>
 <point x="-0.0585352" y="-0.20551" z="0.0752939" active="1" name="belly~right_hind_knee@50"/>
</PickedPoints>
